#include "dspbr/validate/reciprocity.h"

#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/rng.h"

namespace dspbr::validate {

namespace {

// Uniform direction on the hemisphere of the given sign (density 1 / (2 pi)).
Vec3 uniform_hemisphere(Pcg32& rng, double sign) {
  const double z = rng.next_double();
  const double phi = 2.0 * kPi * rng.next_double();
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), sign * z};
}

void accumulate(ReciprocityStats& st, const Vec3& v, const Vec3& l, const Rgb& a, const Rgb& b, double floor) {
  double worst = 0;
  bool counted = false;
  for (int c = 0; c < 3; ++c) {
    const double m = std::max(std::abs(a[c]), std::abs(b[c]));
    if (!(m > floor)) continue;  // also skips NaN (counted by the stability check)
    counted = true;
    worst = std::max(worst, std::abs(a[c] - b[c]) / m);
  }
  if (!counted) return;
  ++st.pairs;
  if (worst > st.max_rel_dev) {
    st.max_rel_dev = worst;
    st.worst_v = v;
    st.worst_l = l;
    st.worst_a = a.max_component();
    st.worst_b = b.max_component();
  }
}
}  // namespace

ReciprocityResult reciprocity_check(const Bsdf& bsdf, const ReciprocitySettings& s) {
  ReciprocityResult r;
  Pcg32 rng(s.seed, 0x7265636970ULL);
  for (std::size_t i = 0; i < s.pairs; ++i) {
    {
      const Vec3 v = uniform_hemisphere(rng, 1), l = uniform_hemisphere(rng, 1);
      accumulate(r.reflection_upper, v, l, bsdf.eval(v, l), bsdf.eval(l, v), s.floor);
    }
    {
      const Vec3 v = uniform_hemisphere(rng, -1), l = uniform_hemisphere(rng, -1);
      accumulate(r.reflection_lower, v, l, bsdf.eval(v, l), bsdf.eval(l, v), s.floor);
    }
    {
      // v above, l below (and by the symmetry of the test, the swapped pair is covered too).
      const Vec3 v = uniform_hemisphere(rng, 1), l = uniform_hemisphere(rng, -1);
      const Rgb fvl = bsdf.eval(v, l), flv = bsdf.eval(l, v);
      const double ev2 = s.eta_above * s.eta_above, el2 = s.eta_below * s.eta_below;
      accumulate(r.transmission_eta2, v, l, fvl / ev2, flv / el2, s.floor);
      accumulate(r.transmission_plain, v, l, fvl, flv, s.floor);
      accumulate(r.transmission_adjoint, v, l, fvl / el2, flv / ev2, s.floor);
    }
  }
  return r;
}

}  // namespace dspbr::validate
