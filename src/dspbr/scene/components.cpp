#include "dspbr/scene/components.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dspbr/material_params.h"

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
      for (Component c : all) known += std::string(known.empty() ? "" : ", ") + component_name(c);
      throw std::invalid_argument("unknown component '" + name + "' (known: " + known + ")");
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

uint32_t active_components(const Material& m, const std::vector<std::string>& scaled_by_texture) {
  std::vector<std::string> ids;  // float / colour parameters only, each once
  for (const auto& id : scaled_by_texture) {
    ParamKind kind;
    try {
      kind = material_parameter_kind(id);
    } catch (const std::invalid_argument&) {
      continue;
    }
    if ((kind == ParamKind::Float || kind == ParamKind::Color) && std::find(ids.begin(), ids.end(), id) == ids.end())
      ids.push_back(id);
  }
  if (ids.size() > 20) throw std::invalid_argument("active_components: too many textured parameters");
  uint32_t mask = 0;
  for (uint32_t corner = 0; corner < (1u << ids.size()); ++corner) {
    Material c = m;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (!(corner >> i & 1u)) continue;  // bit set: this parameter at its lower end, 0
      const bool color = material_parameter_kind(ids[i]) == ParamKind::Color;
      set_material_parameter(c, ids[i], color ? nlohmann::json::array({0.0, 0.0, 0.0}) : nlohmann::json(0.0));
    }
    mask |= active_components(c);
  }
  return mask;
}

std::vector<std::string> tables_for_components(uint32_t mask, bool transmission_compensation) {
  // Every microfacet reflection lobe (metal, dielectric coating, transparent reflection) uses the
  // multiple-scattering compensation M_r,ms F_ms: GGX_E and GGX_E_avg. The opaque dielectric's
  // base B_c needs Base_E and Base_E_avg; sheen layering needs Sheen_E (main model).
  std::vector<std::string> tables;
  const bool specular = mask & (kMetallic | kOpaqueDielectric | kThinTransparent | kVolumetricTransparent | kThinFilm);
  if (specular) {
    tables.push_back("GGX_E");
    tables.push_back("GGX_E_avg");
  }
  if (mask & kOpaqueDielectric) {
    tables.push_back("Base_E");
    tables.push_back("Base_E_avg");
  }
  if (mask & kSheen) tables.push_back("Sheen_E");
  if (transmission_compensation && (mask & kVolumetricTransparent))
    for (const char* t : {"Glass_E", "Glass_inv_E", "Glass_E_avg", "Glass_inv_E_avg"}) tables.push_back(t);
  return tables;
}

}  // namespace dspbr
