#include "dspbr/scene/components.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dspbr/scene/shader_specialization.h"
#include "dspbr/tables/table_registry.h"
#include "dspbr/params/material_params.h"

namespace dspbr {

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
    tables.push_back(lut_name(Lut::GgxE));
    tables.push_back(lut_name(Lut::GgxEAvg));
  }
  if (mask & kOpaqueDielectric) {
    tables.push_back(lut_name(Lut::BaseE));
    tables.push_back(lut_name(Lut::BaseEAvg));
  }
  if (mask & kSheen) tables.push_back(lut_name(Lut::SheenE));
  if (transmission_compensation && (mask & kVolumetricTransparent))
    for (const LutInfo& t : lut_registry())
      if (t.glass && (t.layouts & kPublishedLayout)) tables.push_back(t.name);
  return tables;
}

std::vector<std::string> tables_for_components(uint32_t mask, bool transmission_compensation, LutLayout layout) {
  if (layout == LutLayout::Published) return tables_for_components(mask, transmission_compensation);
  std::vector<std::string> tables;
  for (const ShaderTexture& t : shader_textures(mask)) tables.push_back(t.table);
  if (transmission_compensation && (mask & kVolumetricTransparent))
    for (const LutInfo& t : lut_registry())
      if (t.glass && (t.layouts & kRendererLayout)) tables.push_back(t.name);
  return tables;
}

}  // namespace dspbr
