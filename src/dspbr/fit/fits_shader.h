// Generates fits/dspbr_fits.glsl and fits/dspbr_fits.hlsl from the fit JSON documents: the
// functions of fits/dspbr_fits.hpp (same names, same float arithmetic) for shaders. One body text
// in the syntax GLSL and HLSL share; the coefficient arrays are declared with
// DSPBR_FIT_TABLE(name, n) ... DSPBR_FIT_TABLE_END, which the file defines per dialect unless the
// includer did (tests/test_fit_shaders.cpp compiles the body as C++ against GLM).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace dspbr::fit {

enum class ShaderDialect { Glsl, Hlsl };

// Any document may be null (that part is then left out).
std::string generate_fits_shader(const nlohmann::json& sheen_lambda, const nlohmann::json& albedo,
                                 const nlohmann::json& flake_roughness, ShaderDialect dialect);

}  // namespace dspbr::fit
