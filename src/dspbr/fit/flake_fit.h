// Far-field flakes. When a pixel covers many flakes, the flake
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

// The far-field flake lobe (model): f_agg(v, l) is the mean, over the cap of directions r within
// theta_cone of l, of the density of mirror directions r = reflect(v, n), and that integral is the
// mass of the flake-normal density D(n) n.z over the image of the cap under r -> n = normalize(v + r):
//   f(v, l) = Mass_{D n.z}(image of cap(l)) / Omega_cone      (dr = 4 (v.n) dn)
// In slope space D n.z dn is the GGX slope density P22(x; a) = a^2 / (pi (a^2 + |x|^2)^2), which is
// the Laplacian of ln(a^2 + |x|^2) / (4 pi); by the divergence theorem the mass inside a closed
// curve is (1 / 2 pi) closed integral of (x dy - y dx) / (a^2 + |x|^2) along it: here the image of
// the cap's rim, integrated by the periodic trapezoidal rule with `rim_points` points.
// a = alpha_ggx of the flakes, cos_cone = cos theta_cone (spec "Flakes"); v, l local, z = normal.
double flake_conv_lobe(const Vec3& v, const Vec3& l, double a, double cos_cone, int rim_points);

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

// The cone-convolved lobe against the aggregate for one r_f at views 0, 10, .., 80 deg.
struct FlakeModelView {
  double view_deg, lobe_rel_l2, albedo_aggregate, albedo_model;
};
std::vector<FlakeModelView> flake_conv_model_error(double r_f, int rim_points, bool quick = false);
// alpha_cone^2 of an unclamped cone: Omega / (4 pi - Omega) = tan^2(theta'/2), theta' = 7 deg
// (spec eq. alpha-cone; flake_alpha_cone).
double flake_tan2_half_cone();
// Rim points of the published model (chosen by the study in flake_roughness_fit: errors vs cost).
constexpr int kFlakeRimPoints = 16;

// r_eq(r_f) = r_f (a0 + a1 r_f) / (1 + b1 r_f).
double flake_roughness_formula(double r_f, const std::array<double, 3>& a);
// The documented starting point of the formula fit: r_eq = sqrt(r_f) (a = {1, 0, 0}).
std::array<double, 3> flake_formula_start();

// Runs the per-r_f fits and the formula fit; returns the JSON document (fits/flake_roughness.json
// without command/settings): coefficients, per-r_f table, errors.
nlohmann::json flake_roughness_fit(const FitContext& ctx);

}  // namespace dspbr::fit
