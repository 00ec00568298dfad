#include "dspbr/component.h"
#include "dspbr/nearest_name.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dspbr {

const char* component_name(Component c) {
  switch (c) {
    case kMetallic: return "metallic";
    case kOpaqueDielectric: return "opaque_dielectric";
    case kThinTransparent: return "thin_transparent";
    case kVolumetricTransparent: return "volumetric_transparent";
    case kTranslucency: return "translucency";
    case kThinFilm: return "thin_film";
    case kSheen: return "sheen";
    case kFlakes: return "flakes";
    case kClearcoat: return "clearcoat";
    case kEmission: return "emission";
    case kVolumeAbsorption: return "volume_absorption";
    case kVolumeScattering: return "volume_scattering";
    case kDispersion: return "dispersion";
    default: return "unknown";
  }
}

const std::vector<Component>& all_components() {
  static const std::vector<Component> all{kMetallic, kOpaqueDielectric, kThinTransparent, kVolumetricTransparent,
                                          kTranslucency, kThinFilm, kSheen, kFlakes, kClearcoat, kEmission,
                                          kVolumeAbsorption, kVolumeScattering, kDispersion};
  return all;
}

std::vector<std::string> component_names(uint32_t mask) {
  std::vector<std::string> names;
  for (Component c : all_components())
    if (mask & c) names.push_back(component_name(c));
  return names;
}

uint32_t parse_component_names(const std::vector<std::string>& names) {
  uint32_t mask = 0;
  for (const std::string& name : names) {
    const auto& all = all_components();
    const auto it = std::find_if(all.begin(), all.end(), [&](Component c) { return name == component_name(c); });
    if (it == all.end()) {
      std::string known;
      std::vector<std::string> names_known;
      for (Component c : all) {
        known += std::string(known.empty() ? "" : ", ") + component_name(c);
        names_known.push_back(component_name(c));
      }
      throw std::invalid_argument("unknown component '" + name + "'" + did_you_mean(name, names_known) + " (known: " +
                                  known + ")");
    }
    mask |= *it;
  }
  return mask;
}

uint32_t active_components(const Material& m) {
  uint32_t mask = 0;
  const double dielectric = 1.0 - m.metallic;
  if (m.metallic > 0) mask |= kMetallic;
  if (dielectric > 0 && m.transparency < 1) mask |= kOpaqueDielectric;
  if (dielectric > 0 && m.transparency > 0) mask |= m.thinWalled ? kThinTransparent : kVolumetricTransparent;
  if ((mask & kOpaqueDielectric) && m.translucency > 0) mask |= kTranslucency;
  if (m.thinFilm > 0) mask |= kThinFilm;
  if (m.sheenColor.max_component() > 0) mask |= kSheen;
  if (m.flakeCoverage > 0) mask |= kFlakes;
  if (m.clearcoat > 0) mask |= kClearcoat;
  if (m.emissionValue > 0 && m.emissionColor.max_component() > 0) mask |= kEmission;
  // The volume exists only behind a volume boundary that lets light in.
  const bool volume = !m.thinWalled && (mask & (kVolumetricTransparent | kTranslucency));
  if (volume && std::isfinite(m.attenuationDistance) && m.attenuationColor.min_component() < 1) mask |= kVolumeAbsorption;
  if (volume && m.subsurfaceColor.max_component() > 0) mask |= kVolumeScattering;
  if ((mask & kVolumetricTransparent) && m.abbeNumber > 0) mask |= kDispersion;
  return mask;
}

}  // namespace dspbr
