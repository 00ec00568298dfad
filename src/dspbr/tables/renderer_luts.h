// The renderer layout of the DSPBR energy-compensation tables (docs/luts.md, "Renderer layout"):
// warped endpoint grids, Catmull-Rom lookups, and Base_E / Base_E_avg derived exactly in f0 from
// two GGX moments (no f0 axis to interpolate):
//
//   GGX_E       [roughness][cos_theta]  E_m(mu; r)                       cos axis ggx_cos(p = 0.5; GGX_beta too)
//   GGX_beta    [roughness][cos_theta]  beta - (1 - mu)^5, beta = B / E_m, B = Integral M_r (1 - v.h)^5 mu_l dl
//                                       (the mirror's beta subtracted: 0 on the r = 0 row)
//   GGX_E_avg   [roughness]             ln(1 - E_m,avg), E_m,avg = 2 Integral E^_m mu dmu of the lookup
//   GGX_B_avg   [roughness]             2 Integral B^ mu dmu of the lookup
//   Sheen_E     [alpha_b][cos_theta]    E_b, main sheen                  both axes power(p = 0.25)
//   Sheen_ash_E [alpha_b][cos_theta]    E_b, alternative sheen
//
//   E(mu; r, f0)     = f0 E_m + (1 - f0) B + F_ms(f0, 1; E_m,avg) (1 - E_m),  B = beta E_m      (spec "Energy
//   E_avg(r, f0)     = f0 E_m,avg + (1 - f0) B_avg + F_ms(f0, 1; E_m,avg) (1 - E_m,avg)  Preservation")
//
// The averages are the cosine averages of the directional lookups themselves (integrated from
// the interpolant, float-rounded samples), so the spec's multiple-scattering lobe and B_c built
// from the lookups conserve energy to the lookups' accuracy, also at r -> 0 where 1 - E_m,avg
// vanishes like r^4 (stored as a logarithm for that reason).
//
// Limits: cos_theta in [0, 1] (E_m at cos = 0 is the grazing limit of the integrator, mu = 1e-6);
// roughness in [0, 1] (r = 0: E_m = 1, the r = 0 samples hold the limit of E_m(a alpha; r) as
// r -> 0 at fixed a = mu / alpha); E_m,avg below r = 1e-3 evaluates at r = 1e-3 (1 - E_m,avg
// < 1e-10 there); sheen alpha_b below 1/256 evaluates at 1/256 and cos below 1e-3 at 1e-3 (the
// spec's Lambda fit makes the main sheen's albedo diverge like 1/mu at grazing).
//
// Optional rough-glass tables beyond DSPBR 2025x (docs/luts.md, "Glass tables"; present in the
// default set, absent from sets written before them):
//   Glass_E         [ior][roughness][cos_theta]  E_g(mu; r, ior), v outside   ior axis glass_ior(mu), cos ggx_cos(p = 0.6)
//   Glass_inv_E     [ior][roughness][cos_theta]  E_g, v inside (total internal reflection included)
//   Glass_E_avg     [ior_x][roughness]           2 Integral E^_g mu dmu of the lookup, outside   ior_x axis x^0.5
//   Glass_inv_E_avg [ior_x][roughness]           the same, inside
// ior in [1, 3] (above 3 evaluates at 3); the r = 0 samples hold the limit at fixed mu / alpha
// as for GGX_E.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "dspbr/tables/table_registry.h"
#include "dspbr/tables/warped_table.h"

namespace dspbr {

// The range a lookup clamps its decoded value to: the Catmull-Rom cubic over- and undershoots
// where a table nears its bounds (docs/luts.md, "Limits"). NaN stays NaN (std::clamp).
struct AlbedoRange {
  double lo, hi;
  double clamp(double x) const { return std::clamp(x, lo, hi); }
};
inline constexpr AlbedoRange kEmRange{0.0, 1.0};                                          // E_m
inline constexpr AlbedoRange kSheenERange{0.0, std::numeric_limits<double>::infinity()};  // E_b (both sheens)

struct RendererLuts {
  WarpedTable ggx_E, ggx_beta, ggx_E_avg, ggx_B_avg, sheen_E, sheen_ash_E;
  WarpedTable glass_E, glass_inv_E, glass_E_avg, glass_inv_E_avg;  // optional (has_glass)

  // DSPBR 2025x table names in canonical order, the optional glass tables' names, and the tables
  // by name (nullptr when unknown).
  static const std::vector<const char*>& names();
  static const std::vector<const char*>& glass_names();
  // The tables this set holds: names(), then glass_names() when has_glass().
  std::vector<const char*> held_names() const;
  const WarpedTable* table(const std::string& name) const;
  WarpedTable* table(const std::string& name);
  // The table `id` (std::invalid_argument when it is not in the renderer layout).
  const WarpedTable& table(Lut id) const;
  WarpedTable& table(Lut id);
  size_t stored_values() const;        // number of stored samples of the DSPBR 2025x tables
  size_t glass_stored_values() const;  // ... of the glass tables (0 without them)
  bool has_glass() const;

  // Lookups (arguments: cos theta first, roughness r, alpha_b = r_b^2, f0).
  double E_m(double cos_theta, double roughness) const;
  double B(double cos_theta, double roughness) const;     // Schlick moment = beta E_m
  double beta(double cos_theta, double roughness) const;  // B / E_m
  double E_m_avg(double roughness) const;
  double missing_E_m_avg(double roughness) const;  // 1 - E_m,avg, without cancellation
  double B_avg(double roughness) const;
  double E_base(double cos_theta, double roughness, double f0) const;
  double E_base_avg(double roughness, double f0) const;
  double E_sheen(double cos_theta, double alpha_b) const;

  // The pieces of the Base_E composition (shared with AlbedoSlice):
  // beta from its stored value, beta = (1 - mu)^5 + stored, at least 0 (the interpolating cubic
  // undershoots where beta nears 0: E at f0 = 0 reached -3.5e-4 at r 0.11, cos 0.87; docs/luts.md
  // "Limits");
  static double decode_beta(double mu, double stored) { return std::max(0.0, std::pow(1.0 - mu, 5) + stored); }
  // the same with (1 - mu)^5 by multiplications (equal to rounding; the lobes' per-evaluation form);
  static double decode_beta_fast(double mu, double stored) {
    const double m = 1.0 - mu, m2 = m * m;
    return std::max(0.0, m2 * m2 * m + stored);
  }
  // F_ms(f0, 1; E_m,avg), the base's multiple-scattering Fresnel;
  static double base_fresnel_ms(double f0, double e_m_avg);
  // E = f0 E_m + (1 - f0) B + F_ms (1 - E_m), B = beta E_m (spec "Energy Preservation").
  static double compose_E_base(double f0, double e_m, double beta, double f_ms) {
    return f0 * e_m + (1.0 - f0) * (beta * e_m) + f_ms * (1.0 - e_m);
  }
  double E_sheen_ash(double cos_theta, double alpha_b) const;

  // Rough-glass albedo E_g(mu; r, ior) with v outside (inside = false) or inside, and its cosine
  // average (requires has_glass()).
  double E_glass(double cos_theta, double roughness, double ior, bool inside) const;
  double E_glass_avg(double roughness, double ior, bool inside) const;
};

// Inline: the lookup a caller makes per shading point (LutSet::E_m).
inline double RendererLuts::E_m(double cos_theta, double roughness) const {
  const double r = std::clamp(roughness, 0.0, 1.0);
  const double x0 = ggx_E.axes[0].warp.to_grid(r);
  const double x1 = ggx_E.axes[1].warp.to_grid(cos_theta, r * r);
  return kEmRange.clamp(decode(ggx_E.encoding, ggx_E.interpolate_2d(x0, x1)));
}

// The physical coordinates (one per axis, slowest first; unused ones 0) of sample `index` of a
// renderer-layout table: each axis' warp inverted at its grid coordinate i / (N - 1), the ggx_cos
// axis at alpha = r^2 of the sample's roughness and the glass_ior axis at the sample's cos_theta,
// as a lookup maps them. On an r = 0 row (the limit r -> 0 at fixed mu / alpha) the cos_theta
// coordinates are that limit: 0 below the last sample, 1 at it.
std::array<double, 3> renderer_sample_coordinates(const WarpedTable& t, size_t index);
// The decoded quantity of sample `index` at its `coordinates` (renderer_sample_coordinates), as
// a lookup there decodes it: the table's encoding, and for GGX_beta the mirror's (1 - mu)^5
// added back.
double renderer_sample_value(const WarpedTable& t, size_t index, const std::array<double, 3>& coordinates);

// The default axes (sizes and warps) of a renderer table, `scale` times the default sample count
// per axis (scale 1: the default renderer set, 5184 values; the reference BSDF's set uses 2).
std::vector<WarpedAxis> renderer_default_axes(const std::string& name, int scale = 1);

}  // namespace dspbr
