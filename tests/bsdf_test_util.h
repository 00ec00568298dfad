// Shared helpers of the BSDF tests: the energy tables, direction grids and reference integrals
// computed by Gauss-Legendre quadrature over the sphere (independent of the BSDF's sampling).
#pragma once
#include <cmath>
#include <fstream>
#include <functional>
#include <string>

#include "dspbr/bsdf/bsdf.h"
#include "dspbr/lut/generate.h"
#include "dspbr/lut/lut_set.h"
#include "dspbr/quadrature.h"

namespace dspbr::test {

// The committed renderer tables (luts/dspbr_renderer_luts.json) when present, else a coarse in-memory set generated
// with the project's integrator (few samples: good to ~1e-3, enough for the tolerances used).
inline const LutSet& bsdf_luts() {
  static const LutSet set = [] {
    if (std::ifstream(DSPBR_SOURCE_DIR "/luts/dspbr_renderer_luts.json").good()) return LutSet::builtin();
    LutOptions o;
    o.samples = 2048;
    o.progress = false;
    o.sizes = {{"GGX_E", {32, 32}}, {"GGX_E_avg", {32}}, {"Base_E", {16, 16, 16}},
               {"Base_E_avg", {16, 16}}, {"Sheen_E", {16, 16}}, {"Sheen_ash_E", {16, 16}}};
    LutSet s;
    for (Table& t : generate_luts(o)) {
      if (t.name == "GGX_E") s.ggx_e = t;
      else if (t.name == "GGX_E_avg") s.ggx_e_avg = t;
      else if (t.name == "Base_E") s.base_e = t;
      else if (t.name == "Base_E_avg") s.base_e_avg = t;
      else if (t.name == "Sheen_E") s.sheen_e = t;
      else if (t.name == "Sheen_ash_E") s.sheen_ash_e = t;
    }
    return s;
  }();
  return set;
}

inline Vec3 dir_from_angles(double theta_deg, double phi_deg) {
  const double t = theta_deg * M_PI / 180, p = phi_deg * M_PI / 180;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// Integral over the sphere of g(l) dl, split into the two hemispheres (the BSDF is discontinuous
// at the horizon), composite Gauss-Legendre in mu = cos theta and phi.
inline double integrate_sphere(const std::function<double(const Vec3&)>& g, int mu_panels = 48, int phi_panels = 96) {
  static const QuadratureRule rule = gauss_legendre(8);
  double total = 0;
  for (int hemi = 0; hemi < 2; ++hemi) {
    const double sign = hemi == 0 ? 1.0 : -1.0;
    total += integrate_gl(
        [&](double mu) {
          const double s = std::sqrt(std::max(0.0, 1 - mu * mu));
          return integrate_gl(
              [&](double phi) { return g({s * std::cos(phi), s * std::sin(phi), sign * mu}); }, 0.0, 2 * M_PI,
              phi_panels, rule);
        },
        0.0, 1.0, mu_panels, rule);
  }
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
