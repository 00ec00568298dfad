#include "dspbr/validate/furnace.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

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
  Moments all, nd, dl;
  SampledAlbedo out;
  for (std::size_t i = 0; i < side; ++i) {
    for (std::size_t j = 0; j < side; ++j) {
      const Vec3 u{rng.next_double(), (i + rng.next_double()) / side, (j + rng.next_double()) / side};
      const BsdfSample s = bsdf.sample(v, u);
      if (!s.valid) {
        ++out.invalid;
        all.add(Rgb(0.0));
        nd.add(Rgb(0.0));
        dl.add(Rgb(0.0));
        continue;
      }
      const bool delta = (s.flags & kLobeDelta) != 0;
      all.add(s.weight);
      nd.add(delta ? Rgb(0.0) : s.weight);
      dl.add(delta ? s.weight : Rgb(0.0));
    }
  }
  out.total = all.finish(total, 1.0);
  out.non_delta = nd.finish(total, 1.0);
  out.delta = dl.finish(total, 1.0);
  return out;
}

std::string BoundVerdict::reason() const {
  if (decision != Decision::NotJudged) return {};
  return fmt::format("band ±{:.2g} wider than the tolerance {:g}", band, tolerance);
}

namespace {

// One estimate of the whole integral in one channel, with its band.
struct Estimate {
  double value, band;
  const char* name;
};

// A bound judged over the channels (spec-independent; see furnace.h). `beyond(value, band)`:
// the estimate lies beyond the bound by more than its band; `worse(a, b)`: a is nearer the
// violation than b. `per_channel(c)` lists the estimates of channel c.
template <class Beyond, class Worse, class PerChannel>
BoundVerdict judge_bound(double tolerance, Beyond beyond, Worse worse, PerChannel per_channel) {
  BoundVerdict fail, unjudged, pass;
  bool failed = false, not_judged = false, any_pass = false;
  for (int c = 0; c < 3; ++c) {
    const std::vector<Estimate> est = per_channel(c);
    for (const Estimate& e : est)
      if (beyond(e.value, e.band) && (!failed || worse(e.value, fail.value))) {
        fail = {Decision::Fail, e.value, e.band, tolerance, e.name, true};
        failed = true;
      }
    // The narrower band decides whether the bound could have failed.
    const Estimate* best = &est.front();
    for (const Estimate& e : est)
      if (e.band < best->band) best = &e;
    const BoundVerdict v{best->band <= tolerance ? Decision::Pass : Decision::NotJudged, best->value, best->band,
                         tolerance, best->name, beyond(best->value, 0.0)};
    if (v.decision == Decision::NotJudged) {
      if (!not_judged || v.band > unjudged.band) unjudged = v;
      not_judged = true;
    } else if (!any_pass || worse(v.value, pass.value)) {
      pass = v;
      any_pass = true;
    }
  }
  if (failed) return fail;
  return not_judged ? unjudged : pass;
}

}  // namespace

EnergyVerdict judge_energy(const QuadratureAlbedo& quad, const SampledAlbedo& sampled, const EnergyTolerances& tol) {
  EnergyVerdict v;
  const AlbedoEstimate& t = sampled.total;
  const AlbedoEstimate& nd = sampled.non_delta;
  const AlbedoEstimate& dl = sampled.delta;
  v.albedo_max = t.value.max_component();
  v.albedo_min = t.value.min_component();
  const double k = tol.sigmas;
  // The estimates of the whole integral in channel c: the sampled one, and the quadrature plus the
  // sampled delta part (its band: the delta part's noise plus the quadrature's stated error).
  auto estimates = [&](int c) {
    return std::vector<Estimate>{{t.value[c], k * t.std_error[c], "sampled"},
                                 {quad.value[c] + dl.value[c], k * dl.std_error[c] + quad.error,
                                  "quadrature + sampled delta"}};
  };
  v.conservation = judge_bound(
      tol.conservation, [&](double x, double band) { return x - band > 1.0 + tol.conservation; },
      [](double a, double b) { return a > b; }, estimates);
  v.preservation = judge_bound(
      tol.preservation, [&](double x, double band) { return x + band < 1.0 - tol.preservation; },
      [](double a, double b) { return a < b; }, estimates);
  // Agreement on the non-delta integral: |difference| against the sampled noise and the
  // quadrature's error.
  auto agreement_band = [&](int c) { return k * nd.std_error[c] + quad.error; };
  const double scale = std::max({1.0, quad.value.max_component(), nd.value.max_component()});
  v.agreement = judge_bound(
      tol.agreement_band_max * scale, [&](double d, double band) { return d > band + tol.agreement_abs; },
      [](double a, double b) { return a > b; },
      [&](int c) {
        return std::vector<Estimate>{
            {std::abs(quad.value[c] - nd.value[c]), agreement_band(c), "quadrature vs sampled non-delta"}};
      });
  for (int c = 0; c < 3; ++c)
    v.disagreement = std::max(v.disagreement,
                              std::abs(quad.value[c] - nd.value[c]) / (agreement_band(c) + tol.agreement_abs));
  return v;
}

}  // namespace dspbr::validate
