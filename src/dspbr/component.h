// The DSPBR components a material can activate, as a bit mask (spec "Putting It All Together":
// the layers and cores the BSDF assembles). A component is active when its weight can be non-zero
// somewhere on the material. The reference BSDF takes such a mask so that inactive layers cost
// nothing.
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

}  // namespace dspbr
