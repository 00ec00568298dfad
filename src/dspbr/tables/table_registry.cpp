#include "dspbr/tables/table_registry.h"
#include "dspbr/nearest_name.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

namespace dspbr {

const std::vector<LutInfo>& lut_registry() {
  // Streams: the ids of earlier releases (kept: same seed, same values); published 6 is Base_E's
  // own E_m,avg row (lutgen/generate.cpp).
  static const std::vector<LutInfo> r{
      {Lut::GgxE, "GGX_E", kBothLayouts, true, false, false, false, {"roughness", "cos_theta"}, {32, 32}, 0, 16,
       "E_m(mu; r), GGX single-scattering albedo", "specular and coat energy compensation"},
      {Lut::GgxBeta, "GGX_beta", kRendererLayout, true, false, false, false, {}, {}, kNoStream, 17,
       "beta - (1 - mu)^5, beta = B / E_m", "Base_E composed in f0 (renderer layout)"},
      {Lut::GgxEAvg, "GGX_E_avg", kBothLayouts, true, false, true, false, {"roughness"}, {32}, 1, kNoStream,
       "E_m,avg(r) = 2 Integral E_m mu dmu (renderer: ln(1 - E_m,avg))", "multiple-scattering lobe"},
      {Lut::GgxBAvg, "GGX_B_avg", kRendererLayout, true, false, true, false, {}, {}, kNoStream, kNoStream,
       "2 Integral B mu dmu", "Base_E_avg composed in f0 (renderer layout)"},
      {Lut::BaseE, "Base_E", kPublishedLayout, true, false, false, false, {"f0", "roughness", "cos_theta"},
       {16, 16, 16}, 2, kNoStream, "E(mu; r, f0), metal/dielectric base albedo", "base layering (sheen, coat)"},
      {Lut::BaseEAvg, "Base_E_avg", kPublishedLayout, true, false, true, false, {"f0", "roughness"}, {16, 16}, 3, kNoStream,
       "E_avg(r, f0)", "base layering (sheen, coat)"},
      {Lut::SheenE, "Sheen_E", kBothLayouts, true, false, false, false, {"alpha_b", "cos_theta"}, {16, 16}, 4, 18,
       "E_b(mu; alpha_b), main sheen albedo", "sheen layering"},
      {Lut::SheenAshE, "Sheen_ash_E", kBothLayouts, true, false, false, false, {"alpha_b", "cos_theta"}, {16, 16}, 5, 19,
       "E_b(mu; alpha_b), alternative sheen albedo", "sheen layering (alternative model)"},
      {Lut::GlassE, "Glass_E", kBothLayouts, false, true, false, false, {"ior_x", "roughness", "cos_theta"},
       {16, 16, 32}, 7, 20, "E_g(mu; r, ior), rough dielectric albedo, v outside", "transmission compensation"},
      {Lut::GlassInvE, "Glass_inv_E", kBothLayouts, false, true, false, true, {"ior_x", "roughness", "cos_theta"},
       {16, 16, 32}, 8, 21, "E_g(mu; r, ior), v inside", "transmission compensation"},
      {Lut::GlassEAvg, "Glass_E_avg", kBothLayouts, false, true, true, false, {"ior_x", "roughness"}, {16, 16}, 9, kNoStream,
       "2 Integral E_g mu dmu, outside", "transmission compensation"},
      {Lut::GlassInvEAvg, "Glass_inv_E_avg", kBothLayouts, false, true, true, true, {"ior_x", "roughness"},
       {16, 16}, 10, kNoStream, "2 Integral E_g mu dmu, inside", "transmission compensation"},
  };
  return r;
}

const LutInfo& lut_info(Lut id) { return lut_registry()[size_t(id)]; }

const char* lut_name(Lut id) { return lut_info(id).name; }

const LutInfo* find_lut(const std::string& name, unsigned layouts) {
  for (const LutInfo& t : lut_registry())
    if ((t.layouts & layouts) != 0 && name == t.name) return &t;
  return nullptr;
}

const LutInfo& require_lut(const std::string& name, unsigned layouts) {
  if (const LutInfo* t = find_lut(name, layouts)) return *t;
  throw std::invalid_argument("unknown table '" + name + "'" + did_you_mean(name, lut_names(layouts)) + " (known: " +
                              lut_names_list(layouts) + ")");
}

const LutInfo& published_lut(const std::string& name) { return require_lut(name, kPublishedLayout); }

bool is_lut(const std::string& name, Lut id) { return name == lut_name(id); }

std::vector<std::string> lut_names(unsigned layouts) {
  std::vector<std::string> n;
  for (const LutInfo& t : lut_registry())
    if ((t.layouts & layouts) != 0) n.push_back(t.name);
  return n;
}

std::string lut_names_list(unsigned layouts) { return fmt::format("{}", fmt::join(lut_names(layouts), ", ")); }

const std::vector<std::string>& lut_table_names() {
  static const std::vector<std::string> names = lut_names(kPublishedLayout);
  return names;
}

bool is_lut_table_name(const std::string& name) { return find_lut(name, kPublishedLayout) != nullptr; }

std::vector<std::string> lut_axis_names(const std::string& t) {
  const LutInfo& info = published_lut(t);
  return {info.axes.begin(), info.axes.end()};
}

bool is_glass_table(const std::string& t) {
  const LutInfo* info = find_lut(t, kPublishedLayout);
  return info != nullptr && info->glass;
}

std::vector<int> lut_default_size(const std::string& t) { return published_lut(t).size; }

}  // namespace dspbr
