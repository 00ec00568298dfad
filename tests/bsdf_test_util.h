// Shared helpers of the BSDF tests: the energy tables, direction grids and reference integrals
// computed by Gauss-Legendre quadrature over the sphere (independent of the BSDF's sampling).
#pragma once
#include <cmath>
#include <functional>
#include <string>

#include "dspbr/bsdf/bsdf.h"
#include "dspbr/tables/lut_set.h"
#include "light_space_albedo.h"

namespace dspbr::test {

// The built-in renderer tables (compiled in from luts/dspbr_renderer_luts.json).
inline const LutSet& bsdf_luts() { return LutSet::builtin(); }

inline Vec3 dir_from_angles(double theta_deg, double phi_deg) {
  const double t = theta_deg * M_PI / 180, p = phi_deg * M_PI / 180;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// Integral over the sphere of g(l) dl, split into the two hemispheres (the BSDF is discontinuous
// at the horizon), composite Gauss-Legendre in mu = cos theta and phi (light_space_albedo.h).
inline double integrate_sphere(const std::function<double(const Vec3&)>& g, int mu_panels = 48, int phi_panels = 96) {
  double total = 0;
  for (const double sign : {1.0, -1.0}) total += hemisphere_integral(g, sign, mu_panels, phi_panels);
  return total;
}

// Directional albedo (one channel) Integral f(v, l) |l.z| dl by quadrature.
inline double albedo_quadrature(const Bsdf& b, const Vec3& v, int channel, int mu_panels = 48, int phi_panels = 96) {
  return integrate_sphere([&](const Vec3& l) { return b.eval(v, l)[channel] * std::abs(l.z); }, mu_panels, phi_panels);
}

inline double rel_diff(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300}); }

inline bool finite_nonneg(const Rgb& c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && c.r >= 0 && c.g >= 0 && c.b >= 0;
}

}  // namespace dspbr::test
