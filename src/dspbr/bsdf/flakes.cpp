#include "dspbr/bsdf/flakes.h"

#include <cmath>
#include <limits>

#include "dspbr/constants.h"
#include "dspbr/frame.h"
#include "dspbr/ggx.h"
#include "dspbr/rng.h"

namespace dspbr {

namespace {

// frac(x) = x - floor(x) in [0, 1). x - floor(x) rounds to 1.0 for tiny negative x; 1 is
// equivalent to 0 on the periodic texture, so it is mapped to 0.
double frac(double x) {
  const double f = x - std::floor(x);
  return f < 1.0 ? f : 0.0;
}
double sgn(double x) { return x < 0 ? -1.0 : 1.0; }  // sgn(0) = +1 (the spec leaves it open)

// Omega_cone(cos theta) = 2 pi (1 - cos theta) (spec "Flake BSDF").
double omega_cone(double cos_theta) { return 2.0 * kPi * (1.0 - cos_theta); }
}  // namespace

double flake_count_per_m2(double s_f) {
  if (!(s_f > 0)) return 0.0;                    // no flakes (also NaN)
  const double r = s_f / 2000.0;                 // flake radius in m (spec r_flake)
  const double a_cell = 1.5 * std::sqrt(3.0) * r * r;  // average hexagonal cell area, m^2
  return 1.0 / a_cell;                           // N = 1 / A_avgcell (0 for s_f = inf)
}

int64_t flake_grid_res(double s_f) {
  const double n = flake_count_per_m2(s_f);
  // res = max(4, ceil(sqrt(N / k))) (spec "Flake Texture"); capped, see header.
  const double res = std::max(4.0, std::ceil(std::sqrt(n / kFlakesPerCell)));
  constexpr double kMaxRes = 1099511627776.0;  // 2^40
  return int64_t(std::min(res, kMaxRes));
}

double flake_alpha_cone(double r_f) {
  const double omega = omega_cone(std::cos(kFlakeTargetConeDeg * kPi / 180.0));
  // Spec eq. alpha-cone. Omega / (4 pi - Omega) = tan^2(theta'/2): theta_cone = 7 deg when unclamped.
  const double a2 = std::min(omega / (4.0 * kPi - omega), 0.5 * r_f * r_f);
  return std::sqrt(std::max(0.0, a2));
}

double flake_alpha_ggx(double r_f) {
  const double ac = flake_alpha_cone(r_f);
  return std::sqrt(std::max(0.0, r_f * r_f - ac * ac));  // spec eq. roughness-distribution (>= r_f / sqrt 2)
}

double flake_cos_cone(double r_f) {
  const double a2 = flake_alpha_cone(r_f) * flake_alpha_cone(r_f);
  return 1.0 - 2.0 * a2 / (1.0 + a2);  // spec "Flake BSDF": cos theta_cone = (1 - a^2) / (1 + a^2)
}

FlakeUv flake_triplanar_uv(const Vec3& p, const Vec3& n) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  // Spec eq. tr-mapping: project along the dominant axis of n.
  if (ax > ay && ax > az) return {frac(sgn(p.x) * p.y + 0.5), frac(p.z + 0.5)};
  if (ay > ax && ay > az) return {frac(-sgn(p.y) * p.x + 0.5), frac(p.z + 0.5)};
  return {frac(sgn(p.z) * p.x + 0.5), frac(p.y + 0.5)};
}

Vec3 flake_normal_sample(double alpha_ggx, double u1, double u2) {
  // Spec K(r_f, xi_1, xi_2): w = cos^2 theta = (1 - xi_1) / (1 - (1 - alpha^2) xi_1), the inverse
  // CDF of D(h) (h.n) for GGX. The denominator is >= 1 - xi_1 > 0 for xi_1 in [0, 1).
  const double a2 = alpha_ggx * alpha_ggx;
  const double w = (1.0 - u1) / (1.0 - (1.0 - a2) * u1);
  const double s = std::sqrt(std::max(0.0, 1.0 - w));
  const double phi = 2.0 * kPi * u2;
  return {s * std::cos(phi), s * std::sin(phi), std::sqrt(std::max(0.0, w))};
}

double flake_normal_pdf(const Vec3& h, double alpha_ggx) {
  if (!(alpha_ggx > 0)) return 0.0;  // Dirac at +z
  return GgxDistribution(alpha_ggx, alpha_ggx).D(h) * std::max(0.0, h.z);
}

Flake flake_at(const Vec3& p, const Vec3& n, double f, double s_f, double r_f) {
  Flake out;
  if (!(s_f > 0)) return out;  // flake size 0: no flakes
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return out;  // non-finite p: no flake
  const int64_t res = flake_grid_res(s_f);
  const FlakeUv uv = flake_triplanar_uv(p, n);
  // Continuous grid coordinates and the cell of the shading point (spec eq. grid-cell-coord).
  const double gx = uv.u * double(res), gy = uv.v * double(res);
  const int64_t i = std::min(int64_t(std::floor(gx)), res - 1);
  const int64_t j = std::min(int64_t(std::floor(gy)), res - 1);

  double best_d2 = std::numeric_limits<double>::infinity();
  double best_xi3 = 0, best_xi4 = 0;
  // Probes the k flakes of cell (ii, jj) (unwrapped indices; the texture repeats with period 1 in
  // (u, v), so the hash uses the indices modulo res and the tiling has no seam).
  auto probe = [&](int64_t ii, int64_t jj) {
    const int64_t wi = ((ii % res) + res) % res, wj = ((jj % res) + res) % res;
    Pcg32 rng{static_cast<uint64_t>(wi), static_cast<uint64_t>(wj)};  // per-cell PRNG: PCG32 seeded by (i, j) via SplitMix64
    for (int k = 0; k < kFlakesPerCell; ++k) {
      // 5 sequential numbers per flake (spec generate_flake): position, orientation, opacity.
      const double xi1 = rng.next_double(), xi2 = rng.next_double();
      const double xi3 = rng.next_double(), xi4 = rng.next_double();
      const double xi5 = rng.next_double();
      const double dx = gx - (double(ii) + xi1), dy = gy - (double(jj) + xi2);
      const double d2 = dx * dx + dy * dy;
      if (d2 < best_d2) {  // the intended Voronoi nearest (the spec listing never updates nearest_d)
        best_d2 = d2;
        best_xi3 = xi3;
        best_xi4 = xi4;
        out.opacity = xi5 < f ? 1.0 : 0.0;  // O_f(f, xi_5)
        out.position = {(double(ii) + xi1) / double(res), (double(jj) + xi2) / double(res)};
        out.cell_i = wi;
        out.cell_j = wj;
        out.index = k;
      }
    }
  };
  for (int64_t di = -1; di <= 1; ++di)
    for (int64_t dj = -1; dj <= 1; ++dj) probe(i + di, j + dj);
  // The 3x3 block is exact unless the nearest flake found is farther than the block's border; the
  // own cell always holds a flake within sqrt(2) cells, so the 5x5 block is always exact.
  const double fx = gx - double(i), fy = gy - double(j);
  const double margin = 1.0 + std::min(std::min(fx, 1.0 - fx), std::min(fy, 1.0 - fy));
  if (best_d2 > margin * margin) {
    for (int64_t di = -2; di <= 2; ++di)
      for (int64_t dj = -2; dj <= 2; ++dj)
        if (std::max(std::abs(di), std::abs(dj)) == 2) probe(i + di, j + dj);
  }
  out.normal = flake_normal_sample(flake_alpha_ggx(r_f), best_xi3, best_xi4);
  return out;
}

double flake_cone_bsdf(const Vec3& v, const Vec3& l, const Vec3& n_f, double cos_cone) {
  if (dot(v, n_f) <= 0 || flake_cone_is_delta(cos_cone)) return 0.0;
  const Vec3 r = reflect(v, n_f);  // r = 2 n_f (v.n_f) - v
  return dot(l, r) > cos_cone ? 1.0 / omega_cone(cos_cone) : 0.0;  // spec eq. flake-bsdf
}

double flake_cone_pdf(const Vec3& v, const Vec3& l, const Vec3& n_f, double cos_cone) {
  return flake_cone_bsdf(v, l, n_f, cos_cone);  // uniform in the cone: pdf = 1 / Omega = B_f
}

FlakeConeSample flake_cone_sample(const Vec3& v, const Vec3& n_f, double cos_cone, double u1, double u2) {
  FlakeConeSample s;
  if (dot(v, n_f) <= 0) return s;
  const Vec3 r = normalize(reflect(v, n_f));
  s.valid = true;
  if (flake_cone_is_delta(cos_cone)) {
    s.l = r;
    s.pdf = 1.0;
    s.delta = true;
    return s;
  }
  // Uniform in solid angle within the cone: 1 - cos theta = u1 (1 - cos theta_cone).
  const double one_minus_c = u1 * (1.0 - cos_cone);
  const double c = 1.0 - one_minus_c;
  const double sn = std::sqrt(std::max(0.0, one_minus_c * (2.0 - one_minus_c)));  // sin^2 = (1-c)(1+c)
  const double phi = 2.0 * kPi * u2;
  s.l = Frame::from_normal(r).to_world({sn * std::cos(phi), sn * std::sin(phi), c});
  s.pdf = 1.0 / omega_cone(cos_cone);
  return s;
}

Rgb flake_flip_flop_tint(const Vec3& v, const Vec3& l, const Rgb& rho_f, double f_f, const Rgb& rho_ff) {
  if (!(f_f > 0)) return rho_f;  // f_f = 0 disables the effect (exponent 1/f_f^2 = inf)
  const Vec3 hsum = v + l;
  const double len = length(hsum);
  // v.h_r in [0, 1]; h_r undefined for l = -v: weight 0 (no flip-flop colour).
  const double vh = len > 0 ? std::clamp(dot(v, hsum) / len, 0.0, 1.0) : 0.0;
  return rho_f + (rho_ff - rho_f) * std::pow(vh, 1.0 / (f_f * f_f));  // spec "Flip-Flop Effect"
}

}  // namespace dspbr
