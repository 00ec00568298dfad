#include "dspbr/validate/albedo_quadrature.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dspbr/constants.h"
#include "dspbr/gauss_kronrod.h"

namespace dspbr::validate {

namespace {

// The disc psi < kPsi0 about the peak is one panel in psi (below it a lobe of any roughness the
// catalog holds is flat); beyond it the rule runs in log(psi).
constexpr double kPsi0 = 1e-6;
constexpr int kMaxPanels = 200;

QuadValues<3> to_values(const Rgb& c) { return {c.r, c.g, c.b}; }

// Integral over the hemisphere side * z >= 0 of f(v, l) |l.z| dl, polar about the unit peak p
// (side * p.z >= 0), with absolute tolerance `tol`, split at the cones' jumps.
QuadResult<3> hemisphere(const Bsdf& bsdf, const Vec3& v, const Vec3& p, double side, double tol,
                         const std::vector<FeatureCone>& cones) {
  const Vec3 n{0, 0, side};
  const double pz = std::clamp(side * p.z, 0.0, 1.0);  // cos of p's angle to the normal
  const double e1z = std::sqrt(std::max(0.0, 1.0 - pz * pz));
  // e1: perpendicular to p towards the normal (any perpendicular when p is the normal).
  const Vec3 e1 = e1z > 1e-12 ? normalize(n - pz * p) : Vec3{1, 0, 0};
  const Vec3 e2 = cross(p, e1);
  // The cone psi about p touches the horizon at psi_edge = asin(pz) and leaves the hemisphere at
  // psi_max = pi/2 + acos(pz); between them chi is limited to |chi| <= chi_m with
  // cos(chi_m) = -cos(psi) pz / (sin(psi) e1z), from side * l.z = cos(psi) pz + sin(psi) cos(chi) e1z = 0.
  const double psi_edge = std::asin(pz), psi_max = 0.5 * kPi + std::acos(pz);
  long evaluations = 0;
  // The azimuthal integral at psi (the hemisphere's part of the cone), absolute tolerance t.
  auto ring = [&](double psi, double t) {
    const double cp = std::cos(psi), sp = std::sin(psi);
    double chi_m = kPi;
    if (psi > psi_edge && e1z > 0) chi_m = std::acos(std::clamp(-cp * pz / (sp * e1z), -1.0, 1.0));
    std::vector<double> breaks = {-chi_m, 0.0, chi_m};
    // A cone about a: l.a = cos(psi) p.a + sin(psi) R cos(chi - chi_a) = cos_half_angle on the ring.
    for (const FeatureCone& c : cones) {
      const double a1 = dot(e1, c.axis), a2 = dot(e2, c.axis), r = std::hypot(a1, a2);
      if (!(sp * r > 0)) continue;
      const double x = (c.cos_half_angle - cp * dot(p, c.axis)) / (sp * r);
      if (!(std::abs(x) < 1)) continue;
      const double chi_a = std::atan2(a2, a1), delta = std::acos(x);
      for (double chi : {chi_a - delta, chi_a + delta}) {
        chi = std::remainder(chi, 2 * kPi);
        if (std::abs(chi) < chi_m) breaks.push_back(chi);
      }
    }
    std::sort(breaks.begin(), breaks.end());
    const QuadResult<3> r = integrate_adaptive<3>(
        [&](double chi, QuadValues<3>& out, double& e) {
          const Vec3 l = normalize(cp * p + sp * (std::cos(chi) * e1 + std::sin(chi) * e2));
          const double cos_l = side * l.z;
          e = 0;
          out = cos_l > 0 ? to_values(bsdf.eval(v, l) * cos_l) : QuadValues<3>{};
        },
        breaks, t, kMaxPanels);
    evaluations += r.evaluations;
    return r;
  };
  // Outer rule: the disc in psi, then s = log(psi) with a break every unit and at psi_edge.
  const double s0 = std::log(kPsi0), s1 = std::log(psi_max);
  std::vector<double> breaks;
  for (double s = s0; s < s1; s += 1.0) breaks.push_back(s);
  if (psi_edge > kPsi0) breaks.push_back(std::log(psi_edge));
  // Rings first and last meet a cone at |d - half angle| and d + half angle (d: p to its axis).
  for (const FeatureCone& c : cones) {
    const double d = std::acos(std::clamp(dot(p, c.axis), -1.0, 1.0));
    const double half = std::acos(std::clamp(c.cos_half_angle, -1.0, 1.0));
    for (double psi : {std::abs(d - half), d + half})
      if (psi > kPsi0 && psi < psi_max) breaks.push_back(std::log(psi));
  }
  breaks.push_back(s1);
  std::sort(breaks.begin(), breaks.end());
  const double length = s1 - s0 + kPsi0;
  // Each ring is asked for 0.5 tol / (length w): its errors, weighted by the Jacobian w, add up
  // to at most 0.5 tol; the outer rule's own estimate gets the other half.
  auto outer = [&](double psi, double w, QuadValues<3>& out, double& e) {
    const QuadResult<3> r = ring(psi, 0.5 * tol / (length * std::max(w, 1e-300)));
    for (std::size_t k = 0; k < 3; ++k) out[k] = w * r.value[k];
    e = w * r.error;
  };
  QuadResult<3> disc = integrate_adaptive<3>(
      [&](double psi, QuadValues<3>& out, double& e) { outer(psi, std::sin(psi), out, e); }, {0.0, kPsi0},
      0.5 * tol * kPsi0 / length, kMaxPanels, /*nested_steers=*/false);
  QuadResult<3> rest = integrate_adaptive<3>(
      [&](double s, QuadValues<3>& out, double& e) {
        const double psi = std::exp(s);
        outer(psi, psi * std::sin(psi), out, e);  // dl = sin(psi) dpsi dchi, dpsi = psi ds
      },
      breaks, 0.5 * tol * (s1 - s0) / length, kMaxPanels, /*nested_steers=*/false);
  for (std::size_t k = 0; k < 3; ++k) rest.value[k] += disc.value[k];
  rest.error += disc.error;
  rest.evaluations = evaluations;
  return rest;
}

}  // namespace

Vec3 transmission_peak(const Vec3& v, double eta_ratio) {
  const double side = v.z >= 0 ? 1.0 : -1.0;
  const Vec3 n{0, 0, side};
  Vec3 l;
  if (refract_dir(v, n, eta_ratio, l)) return l;
  return normalize(Vec3{-v.x, -v.y, 0.0});  // total internal reflection (v.x, v.y not both 0 here)
}

QuadratureAlbedo albedo_quadrature(const Bsdf& bsdf, const Vec3& v, double eta_ratio, double tolerance,
                                   const std::vector<FeatureCone>& cones) {
  const double side = v.z >= 0 ? 1.0 : -1.0;
  const QuadResult<3> near = hemisphere(bsdf, v, Vec3{-v.x, -v.y, v.z}, side, 0.5 * tolerance, cones);
  const QuadResult<3> far = hemisphere(bsdf, v, transmission_peak(v, eta_ratio), -side, 0.5 * tolerance, cones);
  QuadratureAlbedo out;
  out.value = Rgb(near.value[0] + far.value[0], near.value[1] + far.value[1], near.value[2] + far.value[2]);
  out.error = near.error + far.error;
  out.evaluations = near.evaluations + far.evaluations;
  return out;
}

}  // namespace dspbr::validate
