// Far-field flakes (issue "Ceres refits", part 3). When a pixel covers many flakes, the flake
// layer's BRDF is the average of the cone BSDF over the flake-normal distribution (spec "Flakes":
// GGX normals with alpha_ggx = sqrt(r_f^2 - alpha_cone^2), density D(n) n.z):
//   f_agg(v, l) = Integral pdf(n) B_f(v, l; n) dn
//               = Integral_{r in cone(l)} pdf(n(r)) B_f / (4 v.n(r)) dr,   n(r) = normalize(v + r)
// (reflection maps normals to directions with dr = 4 (v.n) dn), evaluated by Gauss-Legendre
// quadrature over the small cone around l. It is fitted, per r_f, by the equivalent GGX lobe
// s(v) M_r(v, l; alpha = r_eq^2) (spec "Microfacet BSDF": D G2 / (4 mu_v mu_l)) with one shape
// parameter r_eq for all views and a free scale s(v) per view (the aggregate's albedo falls like
// the view cosine for near-mirror flakes, since B_f is a BRDF evaluated with |l.n|, while the GGX
// lobe's albedo stays near 1), and r_eq(r_f) by a compact formula r_eq = sqrt(r_f) (a0 + a1 r_f)/(1 + b1 r_f)
// (alpha_eq grows like r_f at small r_f: r_f is itself an alpha in the spec, alpha_ggx = sqrt(r_f^2 - alpha_cone^2)).
#pragma once
#include <array>
#include <vector>
#include <nlohmann/json.hpp>

#include "dspbr/fit/fit_common.h"
#include "dspbr/vec3.h"

namespace dspbr::fit {

// Aggregate flake BRDF f_agg(v, l) for flake roughness r_f (v, l in the local frame, z = normal).
double flake_aggregate_brdf(const Vec3& v, const Vec3& l, double r_f);

// Per-r_f fit of r_eq (and the per-view scales) and its errors.
struct FlakeView {
  double cos_view, scale, albedo_aggregate, albedo_ggx;  // albedo_ggx: unscaled GGX lobe, r_eq
};
struct FlakeLobeFit {
  double r_f = 0, r_eq = 0;
  bool converged = false;
  double lobe_rel_l2 = 0;  // worst over the views: ||s M_r mu_l - f_agg mu_l|| / ||f_agg mu_l||
  std::vector<FlakeView> views;
};
FlakeLobeFit fit_flake_lobe(double r_f, bool quick = false);

// r_eq(r_f) = r_f (a0 + a1 r_f) / (1 + b1 r_f).
double flake_roughness_formula(double r_f, const std::array<double, 3>& a);
// The documented starting point of the formula fit: r_eq = sqrt(r_f) (a = {1, 0, 0}).
std::array<double, 3> flake_formula_start();

// Runs the per-r_f fits and the formula fit; returns the JSON document (fits/flake_roughness.json
// without command/settings): coefficients, per-r_f table, errors.
nlohmann::json flake_roughness_fit(const FitContext& ctx);

}  // namespace dspbr::fit
