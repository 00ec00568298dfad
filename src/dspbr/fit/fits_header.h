// Generates fits/dspbr_fits.hpp (self-contained, only <cmath>) from the fit JSON documents
// (fits/sheen_lambda.json, fits/albedo.json, fits/flake_roughness.json). Each function is documented with its domain and the
// measured error read from the same JSON. Coefficients are printed with 9 significant digits
// (round-trip for float).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace dspbr::fit {

// Any document may be null (that part is then left out of the header).
std::string generate_fits_header(const nlohmann::json& sheen_lambda, const nlohmann::json& albedo,
                                 const nlohmann::json& flake_roughness);

// The C++ text of dspbr_fit_flake_lobe (also turned into the shaders' version, fits_shader.h).
std::string flake_lobe_code(const nlohmann::json& flake_roughness);

}  // namespace dspbr::fit
