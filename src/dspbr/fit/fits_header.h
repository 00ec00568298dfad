// Generates fits/dspbr_fits.hpp (self-contained, only <cmath>) from the fit JSON documents
// (fits/sheen_lambda.json, fits/albedo.json, fits/flake_roughness.json). Each function is documented with its domain and the
// measured error read from the same JSON. Coefficients are printed with 9 significant digits
// (round-trip for float).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace dspbr::fit {

// Throws std::invalid_argument naming what is missing or wrong unless `doc` is a fit document of
// `name` (sheen_lambda, albedo, flake_roughness) with every value the generators below read:
// objects where they expect objects, finite numbers within the float range where they read
// numbers, coefficient arrays of the lengths the fitted forms have. (The generators read with
// nlohmann's unchecked const operator[]: an earlier run's document kept by `fit --only` is checked
// with this first.)
void check_fit_document(const std::string& name, const nlohmann::json& doc);

// Any document may be null (that part is then left out of the header).
std::string generate_fits_header(const nlohmann::json& sheen_lambda, const nlohmann::json& albedo,
                                 const nlohmann::json& flake_roughness);

// The C++ text of dspbr_fit_flake_lobe (also turned into the shaders' version, fits_shader.h).
std::string flake_lobe_code(const nlohmann::json& flake_roughness);

}  // namespace dspbr::fit
