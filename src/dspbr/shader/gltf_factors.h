// What a renderer's glTF loader does for the shader library (docs/renderer.md, "From glTF"): the
// factors of one glTF material object into dspbr_shader::DspbrGltf (from "extensions", or "extras"
// as in the validation scenes; glTF's defaults where absent), for dspbr_material_from_gltf. Values
// are taken as they are (the project's importer, src/dspbr/gltf, checks them and reports textures).
#pragma once
#include <nlohmann/json.hpp>

#include "dspbr.h"

namespace dspbr::shader {

dspbr_shader::DspbrGltf gltf_factors(const nlohmann::json& material);

}  // namespace dspbr::shader
