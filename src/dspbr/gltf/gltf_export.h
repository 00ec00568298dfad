// A DSPBR material as a glTF 2.0 material object: the inverse of the mapping of gltf_material.h
// (docs/gltf_mapping.md), for the conformance vectors of the built-in materials (a renderer that
// takes glTF reads the same material from it). Every extension is written with every value
// (KHR_materials_* where they are exact, 3DS_materials_anisotropy / _emission / _sss for what KHR
// cannot say exactly), and the object is mapped back: it is returned only when that gives the
// material again, parameter by parameter (relative 1e-12).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "dspbr/material.h"

namespace dspbr::gltf {

// The glTF material object named `name` that maps to `m`, or null when glTF cannot express `m`
// (flakes, a displaced or bent normal, thin-walled attenuation, ...).
nlohmann::json gltf_material_for(const Material& m, const std::string& name);

}  // namespace dspbr::gltf
