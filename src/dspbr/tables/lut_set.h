// The set of DSPBR energy-compensation tables the BSDF reads, in one of two layouts:
//  - Published: GGX_E, GGX_E_avg, Base_E, Base_E_avg, Sheen_E, Sheen_ash_E on the published
//    cell-centred grids with clamp-to-edge multilinear lookups (what a renderer using the
//    published files computes; tables/table.h);
//  - Renderer: the warped, Catmull-Rom layout of tables/renderer_luts.h (accurate over the whole
//    domain; the default of the reference BSDF).
#pragma once
#include <string>
#include <string_view>

#include "dspbr/tables/renderer_luts.h"
#include "dspbr/tables/table.h"

namespace dspbr {

enum class LutLayout { Published, Renderer };

struct LutSet {
  LutLayout layout = LutLayout::Published;
  // Published layout.
  Table ggx_e;        // [roughness][cos_theta]
  Table ggx_e_avg;    // [roughness]
  Table base_e;       // [f0][roughness][cos_theta]
  Table base_e_avg;   // [f0][roughness]
  Table sheen_e;      // [alpha_b][cos_theta]
  Table sheen_ash_e;  // [alpha_b][cos_theta]
  // Rough-glass tables beyond DSPBR 2025x (lutgen/generate.h; endpoint grids, ior_x = 2 sqrt(F_0));
  // a renderer-layout set holds its own (RendererLuts::glass_*) when its file has them.
  Table glass_e, glass_inv_e;          // [ior_x][roughness][cos_theta]
  Table glass_e_avg, glass_inv_e_avg;  // [ior_x][roughness]
  // Renderer layout.
  RendererLuts renderer;

  // The published table `id` (std::invalid_argument when it is not in the published layout).
  const Table& published_table(Lut id) const;
  Table& published_table(Lut id);

  // Lookups in the tables' own conventions (roughness r, alpha_b = r_b^2), cos theta first.
  double E_m(double cos_theta, double roughness) const;
  double E_m_avg(double roughness) const;
  double missing_E_m_avg(double roughness) const;  // 1 - E_m,avg (exact to its relative precision
                                                   // in the renderer layout)
  double E_base(double cos_theta, double roughness, double f0) const;
  double E_base_avg(double roughness, double f0) const;
  double E_sheen(double cos_theta, double alpha_b) const;
  double E_sheen_ash(double cos_theta, double alpha_b) const;
  // E_g(mu; r, ior) of the rough dielectric interface (lutgen/albedo.h glass_E), v outside or inside,
  // and its cosine average; false from has_glass() when the set holds no glass tables.
  bool has_glass() const;
  double E_glass(double cos_theta, double roughness, double ior, bool inside) const;
  double E_glass_avg(double roughness, double ior, bool inside) const;

  // Reads a table file written by `dspbr lut`: dspbr_luts.json (published layout) or
  // dspbr_renderer_luts.json (renderer layout), told apart by its "format". Throws
  // std::runtime_error with a message naming the file and the problem.
  static LutSet load(const std::string& json_path);
  // The same from the text of such a file; `name` stands for the file in the messages.
  static LutSet from_text(std::string_view text, const std::string& name);
  // The default sets, compiled into the library from the committed luts/dspbr_renderer_luts.json
  // and luts/dspbr_luts.json (parsed once, cached): builtin() is the renderer layout the
  // reference BSDF uses by default, published() the published layout.
  static const LutSet& builtin();
  static const LutSet& published();
  // The embedded text of the default set of a layout and its name in messages and reports
  // ("built-in luts/dspbr_renderer_luts.json", "built-in luts/dspbr_luts.json").
  static std::string_view builtin_text(LutLayout layout);
  static const char* builtin_name(LutLayout layout);
  static const LutSet& of_layout(LutLayout layout);
};

// Inline: the lookup a caller makes per shading point.
inline double LutSet::E_m(double cos_theta, double roughness) const {
  return layout == LutLayout::Renderer ? renderer.E_m(cos_theta, roughness) : ggx_e.lookup_2d(roughness, cos_theta);
}

// "published" / "renderer"; parse_lut_layout throws std::invalid_argument for anything else.
const char* lut_layout_name(LutLayout layout);
LutLayout parse_lut_layout(const std::string& name);

}  // namespace dspbr
