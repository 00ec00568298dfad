// The DSPBR components a material can activate, as a bit mask. Names follow the
// materials/scenes issue ("metallic", "opaque_dielectric", ...). A component is active when its
// weight can be non-zero somewhere on the material. The reference BSDF takes such a mask so that
// inactive layers cost nothing.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dspbr/material.h"

namespace dspbr {

enum Component : uint32_t {
  kMetallic = 1u << 0,
  kOpaqueDielectric = 1u << 1,
  kThinTransparent = 1u << 2,
  kVolumetricTransparent = 1u << 3,
  kTranslucency = 1u << 4,
  kThinFilm = 1u << 5,
  kSheen = 1u << 6,
  kFlakes = 1u << 7,
  kClearcoat = 1u << 8,
  kEmission = 1u << 9,
  kVolumeAbsorption = 1u << 10,
  kVolumeScattering = 1u << 11,
  kDispersion = 1u << 12,
  kAllComponents = (1u << 13) - 1,
};

// Name of one component bit ("metallic", ...); all names in bit order.
const char* component_name(Component c);
const std::vector<Component>& all_components();
std::vector<std::string> component_names(uint32_t mask);
// The mask of a list of component names; throws std::invalid_argument "unknown component 'x'
// (known: metallic, ...)" for a name that is none.
uint32_t parse_component_names(const std::vector<std::string>& names);

// Components whose weight is non-zero for this (untextured) material.
uint32_t active_components(const Material& m);

// Components whose weight can be non-zero somewhere on a textured material: `m` holds the values
// where the textures are 1, and each parameter in `scaled_by_texture` (float or colour ids, e.g.
// "metallic", "sheenColor") may take any value between 0 and its value in `m` (glTF textures
// multiply their factors). Other ids (normals, booleans, enums) are ignored. Every component's
// activity is monotone in each parameter, so the union over the 2^k corners of that box is exact.
uint32_t active_components(const Material& m, const std::vector<std::string>& scaled_by_texture);

// LUT tables (canonical names and order, lut/generate.h) the active components need; with
// transmission_compensation (beyond DSPBR 2025x, docs/bsdf.md) a volumetric transparent
// component also needs the four Glass tables (thin-walled glass needs only GGX_E / GGX_E_avg).
std::vector<std::string> tables_for_components(uint32_t mask, bool transmission_compensation = false);

}  // namespace dspbr
