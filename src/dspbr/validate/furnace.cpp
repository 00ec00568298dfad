#include "dspbr/validate/furnace.h"

#include <cmath>

#include "dspbr/bsdf/sampling.h"
#include "dspbr/constants.h"
#include "dspbr/rng.h"

namespace dspbr::validate {

namespace {

// Running sums for a mean and its standard error, per channel.
struct Moments {
  Rgb sum, sum2;
  void add(const Rgb& x) {
    sum += x;
    sum2 += x * x;
  }
  AlbedoEstimate finish(std::size_t n, double scale) const {
    AlbedoEstimate e;
    e.samples = n;
    if (n == 0) return e;
    const double dn = double(n);
    const Rgb mean = sum / dn;
    e.value = mean * scale;
    Rgb var = sum2 / dn - mean * mean;
    // max(0, .) guards the round-off of E[x^2] - E[x]^2 for (near-)constant integrands.
    var = Rgb(std::max(0.0, var.r), std::max(0.0, var.g), std::max(0.0, var.b));
    const double k = n > 1 ? scale / std::sqrt(dn - 1.0) : 0.0;
    e.std_error = Rgb(std::sqrt(var.r) * k, std::sqrt(var.g) * k, std::sqrt(var.b) * k);
    return e;
  }
};
}  // namespace

AlbedoEstimate albedo_eval(const Bsdf& bsdf, const Vec3& v, int strata, uint64_t seed, uint64_t stream) {
  Pcg32 rng(seed, stream);
  // Each hemisphere is integrated with density |cos|/pi, so each term is pi f(v, l); the two
  // hemispheres are independent estimates that add. Treat them as one sample of their sum.
  Moments m;
  const std::size_t n = std::size_t(strata) * std::size_t(strata);
  for (int i = 0; i < strata; ++i) {
    for (int j = 0; j < strata; ++j) {
      const double u1 = (i + rng.next_double()) / strata, u2 = (j + rng.next_double()) / strata;
      const Vec3 up = sample_cosine_hemisphere(u1, u2);
      const Vec3 down{up.x, up.y, -up.z};
      m.add(bsdf.eval(v, up) + bsdf.eval(v, down));
    }
  }
  return m.finish(n, kPi);
}

SampledAlbedo albedo_sampled(const Bsdf& bsdf, const Vec3& v, std::size_t n, uint64_t seed, uint64_t stream) {
  Pcg32 rng(seed, stream);
  const std::size_t side = std::max<std::size_t>(1, std::size_t(std::sqrt(double(n))));
  const std::size_t total = side * side;
  Moments all, nd;
  SampledAlbedo out;
  for (std::size_t i = 0; i < side; ++i) {
    for (std::size_t j = 0; j < side; ++j) {
      const Vec3 u{rng.next_double(), (i + rng.next_double()) / side, (j + rng.next_double()) / side};
      const BsdfSample s = bsdf.sample(v, u);
      if (!s.valid) {
        ++out.invalid;
        all.add(Rgb(0.0));
        nd.add(Rgb(0.0));
        continue;
      }
      all.add(s.weight);
      nd.add((s.flags & kLobeDelta) ? Rgb(0.0) : s.weight);
    }
  }
  out.total = all.finish(total, 1.0);
  out.non_delta = nd.finish(total, 1.0);
  return out;
}

EnergyVerdict judge_energy(const AlbedoEstimate& eval, const SampledAlbedo& sampled, const EnergyTolerances& tol) {
  EnergyVerdict v;
  const AlbedoEstimate& t = sampled.total;
  const AlbedoEstimate& nd = sampled.non_delta;
  v.albedo_max = t.value.max_component();
  v.albedo_min = t.value.min_component();
  for (int c = 0; c < 3; ++c) {
    // Conservation by both estimators (the eval one sees a gain that a broken sampler would hide).
    if (t.value[c] - tol.sigmas * t.std_error[c] > 1.0 + tol.conservation) v.conserving = false;
    if (eval.value[c] - tol.sigmas * eval.std_error[c] > 1.0 + tol.conservation) v.conserving = false;
    if (t.value[c] + tol.sigmas * t.std_error[c] < 1.0 - tol.preservation) v.preserving = false;
    const double noise = std::hypot(eval.std_error[c], nd.std_error[c]);
    const double bound = tol.sigmas * noise + tol.agreement_abs;
    const double d = std::abs(eval.value[c] - nd.value[c]);
    v.disagreement = std::max(v.disagreement, d / bound);
    if (d > bound) v.estimators_agree = false;
  }
  return v;
}

}  // namespace dspbr::validate
