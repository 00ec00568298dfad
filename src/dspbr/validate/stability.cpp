#include "dspbr/validate/stability.h"

#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/rng.h"

namespace dspbr::validate {

namespace {

Vec3 from_cos_phi(double c, double phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  return {s * std::cos(phi), s * std::sin(phi), c};
}

void classify(StabilityCounts& st, double x) {
  if (std::isnan(x)) ++st.nan;
  else if (std::isinf(x)) ++st.inf;
  else if (x < 0) ++st.negative;
}

void check_eval_pdf(const Bsdf& bsdf, const Vec3& v, const Vec3& l, StabilityCounts& st) {
  const Rgb f = bsdf.eval(v, l);
  for (int c = 0; c < 3; ++c) classify(st, f[c]);
  classify(st, bsdf.pdf(v, l));
  st.evaluations += 2;
}

void check_sample(const Bsdf& bsdf, const Vec3& v, const Vec3& u, double bound, StabilityCounts& st) {
  const BsdfSample s = bsdf.sample(v, u);
  ++st.evaluations;
  if (!s.valid) return;
  for (int c = 0; c < 3; ++c) {
    const double w = s.weight[c];
    classify(st, w);
    if (std::isfinite(w)) {
      if (w > st.max_weight) {
        st.max_weight = w;
        st.max_weight_v = v;
        st.max_weight_u = u;
      }
      if (w > bound) ++st.above_bound;
    }
  }
  classify(st, s.pdf);
  const double len = std::sqrt(dot(s.l, s.l));
  if (std::isnan(len)) ++st.nan;
  else if (!(std::abs(len - 1.0) <= 1e-6)) ++st.bad_direction;
}
}  // namespace

StabilityCounts& StabilityCounts::operator+=(const StabilityCounts& o) {
  evaluations += o.evaluations;
  nan += o.nan;
  inf += o.inf;
  negative += o.negative;
  above_bound += o.above_bound;
  bad_direction += o.bad_direction;
  if (o.max_weight > max_weight) {
    max_weight = o.max_weight;
    max_weight_v = o.max_weight_v;
    max_weight_u = o.max_weight_u;
  }
  return *this;
}

std::vector<Vec3> corner_directions() {
  std::vector<Vec3> d;
  for (double c : {1.0, 1.0 - 1e-12, 0.5, 1e-7, 0.0, -1e-7, -0.5, -1.0})
    for (double phi : {0.0, 2.1}) d.push_back(from_cos_phi(c, phi));
  return d;
}

StabilityCounts stability_scan(const Bsdf& bsdf, const StabilitySettings& s) {
  StabilityCounts st;
  const std::vector<Vec3> dirs = corner_directions();
  // Corner random numbers: the ends of [0, 1) and the middle, in every combination.
  const double us[] = {0.0, 0.5, 1.0 - 0x1.0p-53};
  for (const Vec3& v : dirs) {
    for (const Vec3& l : dirs) check_eval_pdf(bsdf, v, l, st);
    check_eval_pdf(bsdf, v, reflect(v, Vec3{0, 0, 1}), st);  // exact mirror direction
    check_eval_pdf(bsdf, v, -v, st);                          // straight through
    for (double a : us)
      for (double b : us)
        for (double c : us) check_sample(bsdf, v, Vec3{a, b, c}, s.weight_bound, st);
  }
  Pcg32 rng(s.seed, s.stream);
  for (std::size_t i = 0; i < s.random_directions; ++i) {
    const Vec3 v = from_cos_phi(2 * rng.next_double() - 1, 2 * kPi * rng.next_double());
    const Vec3 l = from_cos_phi(2 * rng.next_double() - 1, 2 * kPi * rng.next_double());
    check_eval_pdf(bsdf, v, l, st);
    check_sample(bsdf, v, Vec3{rng.next_double(), rng.next_double(), rng.next_double()}, s.weight_bound, st);
  }
  return st;
}

}  // namespace dspbr::validate
