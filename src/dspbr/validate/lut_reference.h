// Independent high-precision values of the quantities stored in the energy-compensation tables,
// for checking the generated LUTs. The table generator (lutgen/albedo.h) integrates over the light
// direction by (quasi-)Monte Carlo; these functions use a different route: deterministic
// composite Gauss-Legendre quadrature over the microfacet normal h, with the reflected
// l = 2 (v.h) h - v, so that
//   E_m(mu; r)       = Integral D(h) G2(v, l, h) (v.h) / mu dh         (l.n > 0)
//   E(mu; r, f0)     = Integral D G2 F(v.h; f0, 1) (v.h) / mu dh + F_ms(f0, 1) (1 - E_m(mu; r))
//   E_b(mu; alpha_b) = Integral D_b(h) G_b (v.h) / mu dh                (main sheen)
//                    = Integral D_b(h) (l.n) (v.h) / (mu + l.n - mu l.n) dh   (alternative sheen)
// (dl = 4 (v.h) dh for reflection). GGX is integrated in the variable u of its own
// cumulative distribution (tan^2 theta_h = alpha^2 u / (1 - u), where D cos(theta_h) dh = du dphi / 2pi),
// which resolves the peak at any roughness; the Charlie distribution in cos(theta_h) with panels
// refined near the horizon where it peaks. Each value comes with an error estimate: the
// difference to the same rule with half the panels.
//
// The rough-glass tables (beyond DSPBR 2025x) have no second route here: their reference is the
// table generator's deterministic quadrature (lutgen/microfacet_quadrature.h) at target error 1e-6,
// which checks the stored values and the layout's lookups, not the quadrature itself.
#pragma once

#include "dspbr/tables/table_registry.h"

namespace dspbr::validate {

struct RefValue {
  double value = 0;
  double error = 0;  // |value - value with half the panels|
};

// Quadrature effort: panels per dimension (each with 8 Gauss-Legendre nodes).
struct RefQuadrature {
  int panels = 48;
};

RefValue ggx_albedo_ref(double mu, double roughness, const RefQuadrature& q = {});
RefValue ggx_albedo_avg_ref(double roughness, const RefQuadrature& q = {});
RefValue base_albedo_ref(double mu, double roughness, double f0, const RefQuadrature& q = {});
// Integral M_r F(v.h; f0, 1) mu_l dl alone (no multiple-scattering part); f0 = 0 gives the
// Schlick moment E_5 = Integral M_r (1 - v.h)^5 mu_l dl.
RefValue ggx_fresnel_albedo_ref(double mu, double roughness, double f0, const RefQuadrature& q = {});
RefValue base_albedo_avg_ref(double roughness, double f0, const RefQuadrature& q = {});
RefValue sheen_albedo_ref(double mu, double alpha_b, bool alternative, const RefQuadrature& q = {});
// 2 Integral M_r F(v.h; f0, 1) mu_l dl mu dmu: f0 = 0 gives B_avg (the renderer's GGX_B_avg).
RefValue ggx_fresnel_albedo_avg_ref(double roughness, double f0, const RefQuadrature& q = {});
// E_g(mu; r, ior) of the rough dielectric interface (v outside, or inside), and its cosine
// average: the generator's quadrature at target error 1e-6 (see above).
RefValue glass_albedo_ref(double mu, double roughness, double ior, bool inside);
RefValue glass_albedo_avg_ref(double roughness, double ior, bool inside);

// A point of a table's domain in physical coordinates (those a table does not have are ignored).
struct TablePoint {
  double mu = 1, roughness = 0, alpha_b = 0, f0 = 0, ior = 1;
};
// The exact value of the quantity table `id` serves at p (decoded: GGX_E E_m, GGX_beta the Schlick
// moment B = beta E_m, GGX_E_avg E_m,avg, GGX_B_avg B_avg, Base_E E, Base_E_avg E_avg, Sheen_E and
// Sheen_ash_E E_b, the glass tables E_g and its average), with the tables' own clamps (mu >= 1e-6,
// alpha_b >= 1e-3).
RefValue table_quantity_ref(Lut id, const TablePoint& p, const RefQuadrature& q = {});

}  // namespace dspbr::validate
