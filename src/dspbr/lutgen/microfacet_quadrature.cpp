#include "dspbr/lutgen/microfacet_quadrature.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <boost/math/tools/toms748_solve.hpp>

#include "dspbr/constants.h"
#include "dspbr/ggx.h"
#include "dspbr/sheen.h"
#include "dspbr/vec3.h"

namespace dspbr {

namespace {

// The azimuth pieces' variable x in [0, 1] (integrate_normals; built once, not per piece).
const std::vector<double> kUnit = {0.0, 1.0};
// Share of the tolerance left to the azimuthal integrals (the rest to the polar one).
constexpr double kInnerShare = 0.1;
// Polar scan for kinks, then a bracketing root finder to kRootBits bits (4% of a table run less
// than 52 bisections, measured 2026-12-04): kScan points on [0, 1] and, below the first,
// kScanGraded points in geometric progression from kScanLo (the GGX features sit at w ~ alpha,
// down to 1e-6).
constexpr int kScan = 32, kScanGraded = 48;
constexpr double kScanLo = 1e-9;
constexpr int kRootBits = 50, kRootIterations = 100;
// A threshold that does not exist at this polar angle (below every v.h).
constexpr double kAbsent = -2.0;

struct Polar {
  double cz = 0, sz = 0, jac = 0;  // cos, sin of the normal's polar angle; measure factor
};

// x86-64: a second copy of a vectorised function for AVX2 (4 lanes, not SSE2's 2), chosen at load
// time. The same operations in the same order (no FMA: not enabled by the "avx2" target), so the
// same bits on every machine; 1.25x faster glass cells where AVX2 exists.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define DSPBR_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define DSPBR_AVX2_CLONE
#endif

// The nodes of one azimuth panel at a fixed polar angle: c = cos p, sin p, v.h = A c + B and the
// measure's numerator jw (the measure is jw / sin p: dp = dc / sin p).
constexpr int kNodes = 15;  // QK15
struct AzimuthNodes {
  std::array<double, kNodes> c, sin_p, vh, jw;
};

// The nodes of the azimuth piece [a, b] in c = cos p at the panel nodes x = mid + half x_i in
// [0, 1] (x_i the rule's nodes on [-1, 1]; the smoothstep substitution c = a + (b - a)(3 x^2 -
// 2 x^3), integrate_normals), v.h = A c + B and the measure 2 jac dc/dx / sin p, its division
// left to the integrand. Vectorised, as glass_values.
DSPBR_AVX2_CLONE void azimuth_nodes(const std::array<double, kNodes>& x_i, double mid, double half, double a,
                                    double b, double A, double B, double jac, AzimuthNodes& n) {
  for (size_t i = 0; i < size_t(kNodes); ++i) {
    const double x = mid + half * x_i[i], c = a + (b - a) * x * x * (3.0 - 2.0 * x);
    n.c[i] = c;
    n.sin_p[i] = std::sqrt(std::max(0.0, (1.0 - c) * (1.0 + c)));
    n.vh[i] = A * c + B;
    n.jw[i] = 2.0 * jac * (b - a) * 6.0 * x * (1.0 - x);
  }
}

// The integrands that take one node at a time (value(v, h, v.h, out), without the measure) over
// a panel's nodes, times the measure jw / sin p; the nodes at sin p = 0 (the panel's ends, where
// the measure's pole is) add 0.
template <class M>
void values_by_node(const M& m, const Vec3& v, const Polar& p, const AzimuthNodes& n,
                    std::array<QuadValues<M::K>, kNodes>& out) {
  for (size_t i = 0; i < size_t(kNodes); ++i) {
    out[i] = {};
    if (n.sin_p[i] <= 0) continue;
    const Vec3 h{p.sz * n.c[i], p.sz * n.sin_p[i], p.cz};
    m.value(v, h, n.vh[i], out[i]);
    for (double& x : out[i]) x = x * n.jw[i] / n.sin_p[i];
  }
}

// Height-correlated G2(v, l) = 1 / (1 + Lambda(v) + Lambda(l)) of a unit l from its cosine z
// alone (isotropic GGX, Heitz 2014: 1 + Lambda(l) = (|z| + sqrt(z^2 + alpha^2 (1 - z^2))) / (2 |z|)),
// as the fraction G2 = 2 |z| / d: this is d = |z| (1 + 2 Lambda(v)) + sqrt(z^2 + alpha^2 (1 - z^2))
// for g = 1 + 2 Lambda(v), a2 = alpha^2 (no cancellation; the square root's argument clamped
// for |z| > 1 by round-off, so that a vectorised loop can take it whatever the branch).
inline double g2_denominator(double z, double g, double a2) {
  return std::abs(z) * g + std::sqrt(z * z + a2 * std::max(0.0, 1.0 - z * z));
}

// GGX polar variable w (header): cos t = w / sqrt(w^2 + alpha^2 (1 - w^2)) without cancellation
// at w -> 0; D(h) (h.n) dh = 2 w dw dp / (2 pi).
Polar ggx_polar(double alpha, double w) {
  const double s = std::sqrt(std::max(0.0, 1.0 - w * w)) * alpha, d = std::sqrt(w * w + s * s);
  return {w / d, s / d, 2.0 * w / (2.0 * kPi)};
}

// Reflection above the horizon: l.z = 2 (v.h) cos t - mu > 0; more generally v.h where
// l.z = lz.
double reflection_threshold(double mu, double cz, double lz = 0) { return cz > 0 ? (mu + lz) / (2.0 * cz) : 1e300; }

// Layer splits: G2 falls from its value to 0 over l.z in [0, ~alpha] at the horizon (Lambda(l)
// ~ alpha / (2 l.z)), a layer narrower than a piece's first nodes at small roughness. The
// azimuth is also split where |l.z| = kLayer[i] alpha (not kinks: the integrand is smooth there).
constexpr std::array<double, 3> kLayer = {1.0 / 16.0, 0.5, 4.0};

// {E_m, B}: G2 (v.h) / (mu cos t) times {1, (1 - v.h)^5} (the measure in ggx_polar).
struct GgxIntegrand {
  static constexpr int K = 2, kSplits = 4;
  double mu, sv, alpha;
  double lambda_v;
  GgxIntegrand(double mu_, double alpha_)
      : mu(mu_), sv(std::sqrt(std::max(0.0, 1.0 - mu_ * mu_))), alpha(alpha_),
        lambda_v(GgxDistribution(alpha_, alpha_).Lambda(Vec3{sv, 0.0, mu_})) {}
  Polar polar(double w) const { return ggx_polar(alpha, w); }
  // The reflection's horizon, then its layers.
  double split(double cz, int k) const {
    return reflection_threshold(mu, cz, k == 0 ? 0.0 : kLayer[size_t(k - 1)] * alpha);
  }
  void breaks(std::vector<double>&) const {}
  void values(const Vec3&, const Polar& p, const AzimuthNodes& n, std::array<QuadValues<K>, kNodes>& out) const;
};

// GgxIntegrand at one azimuth panel's nodes, vectorised as glass_values (below): l.z = 2 (v.h)
// cos t - mu (reflect(v, h).z), the measure jw / sin p and G2 over one division; 0 where v.h <= 0
// or l.z <= 0 (round-off at a piece's end) and at sin p = 0.
DSPBR_AVX2_CLONE void ggx_values(const AzimuthNodes& n, double mu, double cz, double alpha, double lambda_v,
                                 std::array<QuadValues<2>, kNodes>& out) {
  const double a2 = alpha * alpha, g = 1.0 + 2.0 * lambda_v;
  for (size_t i = 0; i < size_t(kNodes); ++i) {
    const double vh = n.vh[i], lz = 2.0 * vh * cz - mu;
    const double live = (vh > 0 ? 1.0 : 0.0) * (lz > 0 ? 1.0 : 0.0) * (n.sin_p[i] > 0 ? 1.0 : 0.0);
    const double den = live * (g2_denominator(lz, g, a2) * mu * cz * n.sin_p[i]) + (1.0 - live);
    const double w = live * (n.jw[i] * vh * 2.0 * lz / den), m = 1.0 - vh, m2 = m * m;
    out[i][0] = w;
    out[i][1] = w * (m2 * m2 * m);
  }
}

void GgxIntegrand::values(const Vec3&, const Polar& p, const AzimuthNodes& n,
                          std::array<QuadValues<K>, kNodes>& out) const {
  ggx_values(n, mu, p.cz, alpha, lambda_v, out);
}

// The glass integrand (GlassIntegrand, below) at one azimuth panel's nodes: [F_d G2(v, l_r) +
// (1 - F_d) G2(v, l_t)] v.h / (mu cos t) times the measure jw / sin p, the two G2 fractions and the
// measure over one division, F_d's square root the refraction's cos_t. On scalars only: inside
// the class the vectoriser gives up on the loops (measured with -fopt-info-vec: 16.5 ns an
// evaluation node by node, 9.6 ns vectorised, 7.7 ns with AVX2).
DSPBR_AVX2_CLONE void glass_values(const AzimuthNodes& n, double mu, double cz, double alpha, double lambda_v,
                                   double f0, double eta, std::array<QuadValues<1>, kNodes>& out) {
  const double a2 = alpha * alpha, g = 1.0 + 2.0 * lambda_v;
  // Three simple loops (the compiler vectorises each; one loop with everything it does not).
  std::array<double, kNodes> F, lr_z, lt_z;
  const double outside = eta <= 1 ? 1.0 : 0.0;
  for (size_t i = 0; i < size_t(kNodes); ++i) {
    const double vh = n.vh[i];
    const double sin2_t = eta * eta * std::max(0.0, 1.0 - vh * vh);
    const double cos_t = std::sqrt(std::max(0.0, 1.0 - sin2_t));
    // fresnel_schlick_d(vh, f0, 1, eta_i, eta_o): Schlick at v.h (eta <= 1) or at cos_t (<= 1), 1
    // under total internal reflection (sin2_t >= 1 only for eta > 1, or at v.h = 0, where
    // Schlick is 1 too). The side is chosen by a 0/1 blend: a select here stops the vectoriser.
    const double m = 1.0 - (outside * std::min(1.0, vh) + (1.0 - outside) * cos_t), m2 = m * m;
    F[i] = sin2_t >= 1.0 ? 1.0 : f0 + (1.0 - f0) * (m2 * m2 * m);
    lr_z[i] = 2.0 * vh * cz - mu;
    lt_z[i] = -eta * mu + (eta * vh - cos_t) * cz;
  }
  // G2 = 2 |z| / d (g2_denominator), both square roots taken whatever the branch.
  std::array<double, kNodes> d_r, d_t;
  for (size_t i = 0; i < size_t(kNodes); ++i) {
    d_r[i] = g2_denominator(lr_z[i], g, a2);
    d_t[i] = g2_denominator(lt_z[i], g, a2);
  }
  for (size_t i = 0; i < size_t(kNodes); ++i) {
    // 0/1 weights, not selects (which stop the vectoriser; the blends are exact). Under total
    // internal reflection 1 - F = 0 weighs the (meaningless) transmitted term out.
    const double R = lr_z[i] > 0 ? 1.0 : 0.0, T = lt_z[i] < 0 ? 1.0 : 0.0;
    const double dr = R * d_r[i] + (1.0 - R), dt = T * d_t[i] + (1.0 - T);
    // F 2|lr_z| / d_r + (1 - F) 2|lt_z| / d_t over one denominator, with the measure.
    const double num = R * F[i] * 2.0 * lr_z[i] * dt + T * (1.0 - F[i]) * 2.0 * -lt_z[i] * dr;
    const double live = (n.vh[i] > 0 ? 1.0 : 0.0) * (n.sin_p[i] > 0 ? 1.0 : 0.0) * (R + T > 0 ? 1.0 : 0.0);
    const double den = live * (dr * dt * mu * cz * n.sin_p[i]) + (1.0 - live);
    out[i][0] = live * (n.jw[i] * num * n.vh[i] / den);
  }
}

// E_g of the rough dielectric interface (lutgen/albedo.h glass_E).
struct GlassIntegrand {
  static constexpr int K = 1, kSplits = 10;
  double mu, sv, alpha, f0, eta;  // eta = eta_i / eta_o
  double lambda_v, vh_tir;
  GlassIntegrand(double mu_, double alpha_, double f0_, double eta_i_, double eta_o_)
      : mu(mu_), sv(std::sqrt(std::max(0.0, 1.0 - mu_ * mu_))), alpha(alpha_), f0(f0_), eta(eta_i_ / eta_o_),
        lambda_v(GgxDistribution(alpha_, alpha_).Lambda(Vec3{sv, 0.0, mu_})),
        vh_tir(eta > 1 ? std::sqrt(1.0 - 1.0 / (eta * eta)) : kAbsent) {}
  Polar polar(double w) const { return ggx_polar(alpha, w); }
  // The refraction's horizon: l_t.z = -eta mu + (eta v.h - q) cos t with q = sqrt(1 - eta^2 (1 - v.h^2));
  // l_t.z = 0 at v.h = (c^2 + eta^2 - 1) / (2 c eta), c = eta mu / cos t, where eta v.h - q = c >= 0
  // needs c^2 <= eta^2 - 1 (eta > 1 only: for eta <= 1 the refraction is always below). Outside
  // that range the threshold sits at the TIR edge, where it meets it, so it is continuous in t.
  // (With lz < 0: where l_t.z = lz, c = (eta mu + lz) / cos t.)
  double refraction_threshold(double cz, double lz = 0) const {
    if (eta <= 1 || cz <= 0) return kAbsent;
    const double c = (eta * mu + lz) / cz;
    if (c < 0) return kAbsent;
    if (c * c > eta * eta - 1.0) return vh_tir;
    return std::clamp((c * c + eta * eta - 1.0) / (2.0 * c * eta), vh_tir, 1.0);
  }
  // v.h = 0, the reflection's horizon, the TIR edge, the refraction's horizon, then the layers of
  // the two horizons.
  double split(double cz, int k) const {
    switch (k) {
      case 0: return 0.0;
      case 1: return reflection_threshold(mu, cz);
      case 2: return vh_tir;
      case 3: return refraction_threshold(cz);
      default:
        return k < 7 ? reflection_threshold(mu, cz, kLayer[size_t(k - 4)] * alpha)
                     : refraction_threshold(cz, -kLayer[size_t(k - 7)] * alpha);
    }
  }
  void breaks(std::vector<double>&) const {}
  // Only the z components of l_r and l_t enter (their horizons and G2, g2_denominator), in closed form:
  // reflect(v, h).z = 2 (v.h) h.z - mu; the refraction (Walter et al. 2007, eq. 40, as refract_dir)
  // l_t = -eta v + (eta v.h - cos_t) h, cos_t = sqrt(1 - eta^2 (1 - v.h^2)), none under total
  // internal reflection. At eta = 1: l_t = -v, the limit eta -> 1+. F_d from inside is Schlick at
  // the same cos_t (fresnel_schlick_d). Evaluated a panel at a time by glass_values (above).
  void values(const Vec3&, const Polar& p, const AzimuthNodes& n, std::array<QuadValues<K>, kNodes>& out) const {
    glass_values(n, mu, p.cz, alpha, lambda_v, f0, eta, out);
  }
};

// E_b: f_b(v, l) (l.n) 4 (v.h) over dh = d(cos t) dp.
struct SheenIntegrand {
  static constexpr int K = 1, kSplits = 1;
  double mu, sv, alpha_b;
  bool ash;
  SheenLambda lambda;  // the fit at alpha_b and Lambda(v), computed once for the cell
  double lambda_v;
  SheenIntegrand(double mu_, double alpha_b_, bool ash_)
      : mu(mu_), sv(std::sqrt(std::max(0.0, 1.0 - mu_ * mu_))), alpha_b(alpha_b_), ash(ash_),
        lambda(alpha_b_, sheen_lambda_fit_spec()), lambda_v(lambda(mu_)) {}
  Polar polar(double x) const { return {x, std::sqrt(std::max(0.0, 1.0 - x * x)), 1.0}; }
  double split(double cz, int) const { return reflection_threshold(mu, cz); }  // the reflection's horizon
  void values(const Vec3& v, const Polar& p, const AzimuthNodes& n, std::array<QuadValues<K>, kNodes>& out) const {
    values_by_node(*this, v, p, n, out);
  }
  // The Charlie peak at the horizon: sin^(1/alpha_b) t has width ~ sqrt(alpha_b) in cos t.
  void breaks(std::vector<double>& b) const {
    for (double k : {1.0, 3.0, 9.0}) b.push_back(k * std::sqrt(alpha_b));
  }
  void value(const Vec3& v, const Vec3& h, double vh, QuadValues<K>& out) const {
    const Vec3 l = reflect(v, h);
    if (vh <= 0 || l.z <= 0) return;
    out[0] += (ash ? sheen_brdf_ash(v, l, alpha_b) : sheen_brdf(v, l, alpha_b, lambda, lambda_v)) * l.z * 4.0 * vh;
  }
};

// The integral over h of model.value (header), both levels adaptive.
template <class M>
QuadResult<M::K> integrate_normals(const M& m, double tolerance) {
  constexpr int K = M::K;
  const Vec3 v{m.sv, 0.0, m.mu};
  long evaluations = 0;
  const double inner_tol = kInnerShare * tolerance;
  // 2 Integral_0^pi value dp (value is even in p), the measure included, as
  // 2 Integral_-1^1 value dc / sqrt(1 - c^2) in c = cos(p), where v.h = A c + B is linear: the
  // pieces end where v.h crosses a threshold (or a layer split, below).
  auto azimuth = [&](double s, QuadValues<K>& out, double& err) {
    out = {};
    err = 0;
    const Polar p = m.polar(s);
    if (!(p.cz > 0) || p.jac == 0) return;
    const double A = m.sv * p.sz, B = m.mu * p.cz;
    std::array<double, M::kSplits + 2> cs{};
    int n = 0;
    cs[size_t(n++)] = -1.0;
    cs[size_t(n++)] = 1.0;
    for (int k = 0; k < M::kSplits; ++k) {
      const double x = m.split(p.cz, k);
      if (A > 0 && x > B - A && x < B + A) cs[size_t(n++)] = (x - B) / A;
    }
    std::sort(cs.begin(), cs.begin() + n);
    for (int k = 0; k + 1 < n; ++k) {
      const double a = cs[size_t(k)], b = cs[size_t(k + 1)];
      if (b - a < 1e-15) continue;
      // Smoothstep substitution c = a + (b - a)(3 x^2 - 2 x^3): square-root behaviour at the
      // ends (the piece's threshold, 1 / sqrt(1 - c^2) at c = -1 and 1) becomes smooth.
      const QuadResult<K> r = integrate_adaptive<K>(
          [&](double mid, double half, std::array<QuadValues<K>, kNodes>& vals, std::array<double, kNodes>& es) {
            AzimuthNodes nodes;
            azimuth_nodes(GaussKronrod<kNodes>::get().x, mid, half, a, b, A, B, p.jac, nodes);
            es = {};
            m.values(v, p, nodes, vals);
          },
          kUnit, inner_tol / (n - 1), kQuadMaxPanels);
      evaluations += r.evaluations;
      for (int c = 0; c < K; ++c) out[size_t(c)] += r.value[size_t(c)];
      err += r.error;
    }
  };
  // Kinks: where a threshold meets v.h at p = 0 (cos(t_v - t)) or p = pi (cos(t_v + t)).
  // The layer splits are polar breaks too (at normal incidence the layer lies across t alone).
  // Gap 2k (2k + 1): split k minus v.h at p = 0 (p = pi).
  constexpr int kSplits = M::kSplits;
  auto gap = [&](double s, int g) {
    const Polar p = m.polar(s);
    const double A = m.sv * p.sz, B = m.mu * p.cz;
    return m.split(p.cz, g / 2) - (g % 2 == 0 ? B - A : B + A);
  };
  auto gaps = [&](double s, std::array<double, 2 * kSplits>& d) {
    const Polar p = m.polar(s);
    const double A = m.sv * p.sz, B = m.mu * p.cz;
    for (int k = 0; k < kSplits; ++k) {
      const double t = m.split(p.cz, k);
      d[size_t(2 * k)] = t - (B - A);
      d[size_t(2 * k + 1)] = t - (B + A);
    }
  };
  std::vector<double> breaks = {0.0, 1.0};
  m.breaks(breaks);
  std::array<double, 2 * kSplits> prev{}, cur{};
  static const std::vector<double> scan = [] {
    std::vector<double> x;
    for (int i = 0; i < kScanGraded; ++i) x.push_back(kScanLo * std::pow(1.0 / (kScan * kScanLo), double(i) / kScanGraded));
    for (int i = 1; i <= kScan; ++i) x.push_back(double(i) / kScan);
    return x;
  }();
  double s_prev = scan[0];
  gaps(s_prev, prev);
  for (size_t i = 1; i < scan.size(); ++i) {
    const double s = scan[i];
    gaps(s, cur);
    for (size_t k = 0; k < cur.size(); ++k) {
      if ((prev[k] < 0) == (cur[k] < 0)) continue;
      // TOMS 748 (Alefeld, Potra and Shi 1995): it keeps a bracket, so a jump of the split (a
      // layer that vanishes) is found as a root is.
      boost::uintmax_t iterations = kRootIterations;
      const std::pair<double, double> root = boost::math::tools::toms748_solve(
          [&](double x) { return gap(x, int(k)); }, s_prev, s, prev[k], cur[k],
          boost::math::tools::eps_tolerance<double>(kRootBits), iterations);
      breaks.push_back(0.5 * (root.first + root.second));
    }
    prev = cur;
    s_prev = s;
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::remove_if(breaks.begin(), breaks.end(), [](double b) { return b < 0 || b > 1; }), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  QuadResult<K> r = integrate_adaptive<K>(azimuth, breaks, (1.0 - kInnerShare) * tolerance, kQuadMaxPanels);
  r.evaluations = evaluations;
  return r;
}

}  // namespace

QuadResult<2> ggx_moments_quadrature(double mu, double alpha, double tolerance) {
  return integrate_normals(GgxIntegrand(mu, alpha), tolerance);
}

QuadResult<1> dielectric_albedo_quadrature(double mu, double alpha, double f0, double eta_i, double eta_o,
                                      double tolerance) {
  return integrate_normals(GlassIntegrand(mu, alpha, f0, eta_i, eta_o), tolerance);
}

QuadResult<1> sheen_albedo_quadrature(double mu, double alpha_b, bool ash, double tolerance) {
  return integrate_normals(SheenIntegrand(mu, alpha_b, ash), tolerance);
}

}  // namespace dspbr
