// The rough-glass tables and the compensated transparent core (beyond DSPBR 2025x; docs/luts.md
// "Glass tables", docs/bsdf.md "Transmission compensation"), checked against integrals computed
// another way: Gauss-Legendre quadrature of the lobes' own eval over the half vector (slope
// domain, fixed panels, no thresholds) for the tables, over the light direction (mu_l, phi) for
// the furnace of the compensated BSDF (no sampling), and the eta^2 rule of the volumetric BTDF.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/bsdf/microfacet_reflection.h"
#include "dspbr/bsdf/volumetric_transmission.h"
#include "dspbr/constants.h"
#include "dspbr/fresnel.h"
#include "dspbr/lutgen/albedo.h"
#include "dspbr/lutgen/generate.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/lutgen/renderer_io.h"
#include "dspbr/tables/renderer_luts.h"
#include "dspbr/material.h"
#include "dspbr/quadrature.h"
#include "dspbr/rng.h"
#include "dspbr/scene/components.h"
#include "light_space_albedo.h"
#include "test_lut_reference.h"

namespace dspbr {
namespace {

// Integral of g(l) |l.z| over one hemisphere (sign +1 upper, -1 lower) in (mu_l, phi), the mu
// axis graded towards the horizon (light_space_albedo.h; v in the xz plane, phi over [0, 2 pi]
// with twice the panels: the nodes of [0, pi] mirrored).
template <class G>
double hemisphere_albedo(G&& g, double sign, int panels) {
  return test::hemisphere_integral([&](const Vec3& l) { return g(l) * std::abs(l.z); }, sign, panels, 2 * panels,
                                   test::MuGrading::Horizon);
}

// The integrand of ggx_half_vector_integral (measure D(h) (h.n) dh) for the light-space
// integrand f(l) |l.z| at the directions of half vector h: f_r at l = reflect(v, h), Jacobian
// dl/dh = 4 |v.h|, and (refract) f_t at l = refract(v, h), Jacobian (eta_i v.h + eta_o l.h)^2 /
// (eta_o^2 |l.h|) (Walter et al. 2007 eq. 14 and 17).
template <class R, class T>
double half_vector_terms(const Vec3& v, const Vec3& h, double alpha, double eta_i, double eta_o, bool refract, R&& f_r,
                         T&& f_t) {
  const double vh = dot(v, h);
  if (vh <= 0) return 0.0;
  const double dh = GgxDistribution(alpha, alpha).D(h) * h.z;
  double sum = 0;
  const Vec3 lr = reflect(v, h);
  if (lr.z > 0) sum += f_r(lr) * lr.z * 4.0 * vh / dh;
  Vec3 lt;
  if (refract && refract_dir(v, h, eta_i / eta_o, lt) && lt.z < 0) {
    const double lh = dot(lt, h), den = eta_i * vh + eta_o * lh;
    sum += f_t(lt) * -lt.z * den * den / (eta_o * eta_o * std::abs(lh)) / dh;
  }
  return sum;
}

// E_g from the BSDF's own lobes over the half vector (the slope parametrisation of test_lut_reference.h, graded
// towards tilted normals): each lobe's eval at l = reflect(v, h) or refract(v, h) times |l.z| and
// the Jacobian dl/dh (4 |v.h| for reflection, (eta_i v.h + eta_o l.h)^2 / (eta_o^2 |l.h|) for
// refraction, Walter et al. 2007 eq. 14 and 17), divided by the measure's D(h) (h.n).
double glass_albedo_half_vector(double mu, double r, double ior, bool inside, int panels) {
  const double alpha = r * r, eta_i = inside ? ior : 1.0, eta_o = inside ? 1.0 : ior;
  const double f0 = f0_from_ior(1.0, ior);
  const MicrofacetReflection refl(alpha, alpha, [=](double c) {
    return Rgb(fresnel_schlick_d(c, f0, 1.0, eta_i, eta_o));
  });
  const VolumetricTransmission trans(alpha, alpha, eta_i, eta_o, [=](double c) {
    return Rgb(1.0 - fresnel_schlick_d(c, f0, 1.0, eta_i, eta_o));
  });
  const Vec3 v{std::sqrt(1.0 - mu * mu), 0.0, mu};
  return lutref::ggx_half_vector_integral(
      alpha,
      [&](const Vec3& h) {
        return half_vector_terms(
            v, h, alpha, eta_i, eta_o, true, [&](const Vec3& l) { return refl.eval(v, l).r; },
            [&](const Vec3& l) { return trans.eval(v, l).r; });
      },
      panels, panels);
}

IntegratorSettings quad_settings() {
  IntegratorSettings s;
  s.integrator = Integrator::Quad;
  s.samples = 8 << 16;
  s.target_error = kLutDefaultTargetError;
  return s;
}

struct GlassPoint {
  double mu, r, ior;
};
const GlassPoint kPoints[] = {{0.9, 0.5, 1.5},  {0.5, 0.5, 1.5}, {0.15, 0.6, 1.33},
                              {0.7, 0.7, 2.0},  {0.3, 0.8, 3.0}, {0.6, 0.4, 1.2}};

TEST(GlassAlbedo, QuadMatchesHalfVectorQuadratureOfTheLobes) {
  for (const bool inside : {false, true})
    for (const GlassPoint& p : kPoints) {
      const double ref = glass_albedo_half_vector(p.mu, p.r, p.ior, inside, 64);
      const double ref_coarse = glass_albedo_half_vector(p.mu, p.r, p.ior, inside, 32);
      ASSERT_LT(std::abs(ref - ref_coarse), 5e-5)
          << "reference not converged: mu " << p.mu << " r " << p.r << " ior " << p.ior << " inside " << inside;
      const Estimate e = glass_E(p.mu, p.r, p.ior, inside, quad_settings());
      EXPECT_NEAR(e.value, ref, 1e-4) << "mu " << p.mu << " r " << p.r << " ior " << p.ior << " inside " << inside;
      EXPECT_LE(e.error, 1e-4);
    }
}

TEST(GlassAlbedo, QmcAndQuadAgreeWithinTheQmcError) {
  IntegratorSettings q;
  q.samples = 8 << 14;
  for (const bool inside : {false, true})
    for (const GlassPoint& p : kPoints) {
      const Estimate a = glass_E(p.mu, p.r, p.ior, inside, q);
      const Estimate b = glass_E(p.mu, p.r, p.ior, inside, quad_settings());
      EXPECT_NEAR(a.value, b.value, 6 * a.error + 2e-5);
    }
}

TEST(GlassAlbedo, GrazingLowRoughnessCellsWithinTheTrueErrorBound) {
  // Cells where the quadrature's embedded estimate misses its error (found by comparing 5632
  // cells of the renderer grid with a 1e-10 run; that run agrees with QMC at 2^25 samples within
  // its 1e-7 standard error at each of these, measured 2026-12-04). At the default target the
  // table cell must be within 1e-6 of it (asked at the target itself, the first cell was 1.1e-6
  // off); the stated error bounds the truth at the first two and the last, not at the third and
  // fourth (3.1e-7 and 1.2e-7 true, a tenth of that stated: docs/luts.md, "Glass tables"). The
  // last is the reason the safety factor reaches r = 1/4 (without it: 2.2e-7 true, 4.8e-8 stated).
  struct Cell {
    double mu, r, ior;
    bool inside, stated_bounds;
  };
  const Cell cells[] = {{2.991e-4, 1.0 / 15, 1.91674, false, true},
                        {2.5640712208942706e-4, 1.0 / 15, 1.6803559458335713, false, true},
                        {0.003631, 1.0 / 15, 1.00005, false, false},
                        {0.3294, 11.0 / 15, 1.03003, true, false},
                        {0.427, 0.2, 1.25997, true, true}};
  IntegratorSettings table = quad_settings(), tight = quad_settings();
  table.target_error = kQuadDefaultTolerance;  // the tables' default
  tight.target_error = 1e-9;  // run at 1e-10 below r = 1/4 (the glass safety factor); tighter runs hit the panel cap
  for (const Cell& c : cells) {
    const Estimate e = glass_E(c.mu, c.r, c.ior, c.inside, table);
    const Estimate ref = glass_E(c.mu, c.r, c.ior, c.inside, tight);
    const double err = std::abs(e.value - ref.value);
    EXPECT_LE(err, 1e-6) << "mu " << c.mu << " r " << c.r << " ior " << c.ior << " inside " << c.inside;
    EXPECT_LE(e.error, kQuadDefaultTolerance);
    if (c.stated_bounds) EXPECT_LE(err, e.error + ref.error) << "mu " << c.mu << " ior " << c.ior;
  }
}

TEST(GlassAlbedo, LimitsInClosedForm) {
  // Smooth interface: reflection F_d + transmission (1 - F_d) = 1 on both sides (also under total
  // internal reflection, where F_d = 1).
  for (const bool inside : {false, true})
    for (double mu : {0.05, 0.5, 1.0}) EXPECT_NEAR(glass_E(mu, 0.0, 1.5, inside, quad_settings()).value, 1.0, 1e-12);
  // ior = 1 holds the limit ior -> 1+ of the rough M_t (the BSDF's Dirac at exactly 1 aside).
  for (double r : {0.3, 0.7})
    EXPECT_NEAR(glass_E(0.5, r, 1.0, false, quad_settings()).value, glass_E(0.5, r, 1.0001, false, quad_settings()).value,
                1e-3);
}

TEST(GlassTables, CommittedCellsMatchIndependentQuadrature) {
  const LutSet& luts = LutSet::published();
  ASSERT_TRUE(luts.has_glass());
  for (const Table* t : {&luts.glass_e, &luts.glass_inv_e}) {
    const bool inside = t == &luts.glass_inv_e;
    const Axis &ax = t->axes[0], &ar = t->axes[1], &am = t->axes[2];
    // Cells spread over the axes where the slope-domain reference converges at 64 panels (r >= 0.2,
    // cos theta < 1: at normal incidence from inside it is off by up to 3e-4, while QMC with 2^24
    // samples agrees with the table to 1e-9 there, docs/luts.md).
    for (int ix : {1, ax.size / 2, ax.size - 1})
      for (int ir : {ar.size - 1, ar.size / 2, ar.size / 4})
        for (int im : {2, am.size / 2, am.size - 2}) {
          const double r = ar.coord(ir), mu = am.coord(im), ior = glass_ior_of_x(ax.coord(ix));
          if (r < 0.2) continue;
          const double ref = glass_albedo_half_vector(mu, r, ior, inside, 64);
          EXPECT_NEAR(t->at({ix, ir, im}), ref, 1e-4) << t->name << " ior " << ior << " r " << r << " mu " << mu;
        }
  }
}

TEST(GlassTables, AveragesMatchTheCosineAverageOfTheDirectionalValues) {
  const LutSet& luts = LutSet::published();
  static const QuadratureRule rule = gauss_legendre(8);
  for (const bool inside : {false, true})
    for (double r : {0.5, 1.0})
      for (double ior : {1.33, 2.0}) {
        const double avg = integrate_gl(
            [&](double mu) { return 2.0 * mu * glass_E(mu, r, ior, inside, quad_settings()).value; }, 0.0, 1.0, 4, rule);
        const Estimate e = glass_E_avg(r, ior, inside, quad_settings());
        EXPECT_NEAR(e.value, avg, 1e-4) << "r " << r << " ior " << ior << " inside " << inside;
        // The committed table through its lookup (which interpolates in ior and r).
        EXPECT_NEAR(luts.E_glass_avg(r, ior, inside), avg, 2e-3);
      }
}

// ---- The renderer layout of the glass tables (warped Catmull-Rom lookups) --------------------

// Off-grid points over the whole domain: ior 1..3 (a third within 1.1), roughness 0.02..1,
// cos theta 1e-3..1 (a third below 0.05). Seeded: the same points every run.
std::vector<GlassPoint> random_glass_points(int n, double r_lo) {
  Pcg32 rng(11, 5);
  std::vector<GlassPoint> out;
  for (int k = 0; k < n; ++k) {
    GlassPoint p;
    p.mu = k % 3 == 0 ? std::pow(10.0, -3.0 + 1.7 * rng.next_double()) : 1e-3 + (1 - 1e-3) * rng.next_double();
    p.r = r_lo + (1 - r_lo) * rng.next_double();
    p.ior = k % 3 == 1 ? 1.0 + 0.1 * std::pow(rng.next_double(), 2) : 1.0 + 2.0 * rng.next_double();
    out.push_back(p);
  }
  return out;
}

TEST(GlassRenderer, LookupsMatchIndependentQuadrature) {
  const RendererLuts& L = LutSet::builtin().renderer;
  ASSERT_TRUE(L.has_glass());
  // Against the lobes' own eval integrated over the half vector (independent of the tables'
  // integrator), where that reference converges (r >= 0.2, cos theta in [0.02, 0.95]).
  for (const bool inside : {false, true})
    for (const GlassPoint& p : random_glass_points(24, 0.2)) {
      const double mu = std::clamp(p.mu, 0.02, 0.95);
      const double ref = glass_albedo_half_vector(mu, p.r, p.ior, inside, 64);
      EXPECT_NEAR(L.E_glass(mu, p.r, p.ior, inside), ref, 2e-3)
          << "mu " << mu << " r " << p.r << " ior " << p.ior << " inside " << inside;
    }
  // Over the whole domain (grazing, ior -> 1, r -> 0) against the deterministic quadrature at a
  // tenth of the tables' target error: the interpolation error of the layout.
  IntegratorSettings fine = quad_settings();
  fine.target_error = 1e-6;
  for (const bool inside : {false, true}) {
    double max_err = 0, sum2 = 0;
    const std::vector<GlassPoint> pts = random_glass_points(150, 0.02);
    for (const GlassPoint& p : pts) {
      const double e = L.E_glass(p.mu, p.r, p.ior, inside) - glass_E(p.mu, p.r, p.ior, inside, fine).value;
      max_err = std::max(max_err, std::abs(e));
      sum2 += e * e;
    }
    const double rms = std::sqrt(sum2 / double(pts.size()));
    std::printf("Glass%s_E renderer lookup: max %.2e rms %.2e over %zu points\n", inside ? "_inv" : "", max_err, rms,
                pts.size());
    EXPECT_LE(max_err, 5e-3) << (inside ? "inside" : "outside");
    EXPECT_LE(rms, 1e-3) << (inside ? "inside" : "outside");
  }
}

TEST(GlassRenderer, AveragesAreTheCosineAveragesOfTheLookups) {
  // A separate rule from the generator's (which follows the cos grid): Gauss-Legendre in mu^(1/4),
  // 64 panels of 8 nodes, dense where the grazing drop is.
  const RendererLuts& L = LutSet::builtin().renderer;
  static const QuadratureRule rule = gauss_legendre(8);
  for (const bool inside : {false, true})
    for (double r : {0.0, 0.3, 0.55, 1.0})
      for (double ior : {1.0, 1.05, 1.5, 2.2, 3.0}) {
        const double avg = integrate_gl(
            [&](double t) {
              const double mu = t * t * t * t;
              return 2.0 * mu * L.E_glass(mu, r, ior, inside) * 4.0 * t * t * t;
            },
            0.0, 1.0, 64, rule);
        const auto& ax = L.glass_E_avg.axes;
        auto on_sample = [](const WarpedAxis& a, double v) {
          const double c = a.warp.to_grid(v) * (a.size - 1);
          return std::abs(c - std::round(c)) < 1e-9;
        };
        const bool on_grid = on_sample(ax[0], glass_x_of_ior(ior)) && on_sample(ax[1], r);
        // On the average table's grid the stored value is the average itself; between samples the
        // average table interpolates (smooth in ior_x and r).
        EXPECT_NEAR(L.E_glass_avg(r, ior, inside), avg, on_grid ? 2e-5 : 1e-3)
            << "r " << r << " ior " << ior << " inside " << inside;
      }
}

TEST(GlassRenderer, FileRoundTripAndPartialSetsRefused) {
  const RendererLuts& L = LutSet::builtin().renderer;
  const std::string text = renderer_json_text(L, LutOptions{}, 1);
  const RendererLuts back = read_renderer_json_text(text, "round trip");
  ASSERT_TRUE(back.has_glass());
  for (const char* n : RendererLuts::glass_names()) {
    EXPECT_EQ(back.table(n)->values, L.table(n)->values) << n;
    ASSERT_EQ(back.table(n)->axes.size(), L.table(n)->axes.size()) << n;
    for (size_t d = 0; d < L.table(n)->axes.size(); ++d)
      EXPECT_EQ(int(back.table(n)->axes[d].warp.kind), int(L.table(n)->axes[d].warp.kind)) << n;
  }
  // Three of the four glass tables: refused, naming the missing one.
  nlohmann::json j = nlohmann::json::parse(text);
  j["tables"].erase("Glass_inv_E_avg");
  try {
    (void)read_renderer_json_value(j, "partial.json");
    ADD_FAILURE() << "a partial glass set was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("Glass_inv_E_avg is missing"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("partial.json"), std::string::npos) << e.what();
  }
  // None of them: a set without glass (the BSDF then falls back to the published ones).
  for (const char* n : RendererLuts::glass_names()) j["tables"].erase(n);
  EXPECT_FALSE(read_renderer_json_value(j, "no_glass.json").has_glass());
}

// ---- The compensated transparent core ---------------------------------------------------------

Material white_glass(double r, double ior, bool thin) {
  Material m;
  m.transparency = 1;
  m.roughness = r;
  m.ior = ior;
  m.thinWalled = thin;
  return m;
}

// Directional albedo of the whole BSDF (both hemispheres) by light-domain quadrature.
double furnace(const Bsdf& b, double mu, int panels) {
  const Vec3 v{std::sqrt(1.0 - mu * mu), 0.0, mu};
  auto g = [&](const Vec3& l) { return b.eval(v, l).r; };
  return hemisphere_albedo(g, 1.0, panels) + hemisphere_albedo(g, -1.0, panels);
}

// White-furnace albedo of the compensated white glass `on` at view cosine mu (inside: the viewer
// in the medium), integrating eval only: the uncompensated BSDF `off` (sharp lobes) over the half
// vector, through the reflection map l = reflect(v, h) (Jacobian 4 v.h) for the upper hemisphere
// and the refraction map (volumetric; Walter et al. 2007 eq. 17) or the mirrored reflection
// (thin-walled) for the lower one; and the difference on - off (the compensation lobes, smooth)
// over the light direction.
double compensated_furnace(const MaterialBsdf& on, const MaterialBsdf& off, double mu, double r, double ior, bool thin,
                           bool inside) {
  const double alpha = r * r, eta_i = inside && !thin ? ior : 1.0, eta_o = inside || thin ? 1.0 : ior;
  const Vec3 v{std::sqrt(1.0 - mu * mu), 0.0, mu};
  // Local frame of the side: a viewer inside sees the mirrored configuration (material_bsdf.h).
  auto eval = [&](const MaterialBsdf& b, const Vec3& vl, const Vec3& ll) {
    return inside ? b.eval(-1.0 * vl, -1.0 * ll).r : b.eval(vl, ll).r;
  };
  // Thin-walled: the lower hemisphere through the mirrored reflection (same Jacobian).
  const double sharp = lutref::ggx_half_vector_integral(
      alpha,
      [&](const Vec3& h) {
        return half_vector_terms(
            v, h, alpha, eta_i, eta_o, !thin,
            [&](const Vec3& l) { return eval(off, v, l) + (thin ? eval(off, v, Vec3{l.x, l.y, -l.z}) : 0.0); },
            [&](const Vec3& l) { return eval(off, v, l); });
      },
      48, 48);
  auto diff = [&](const Vec3& l) { return eval(on, v, l) - eval(off, v, l); };
  return sharp + hemisphere_albedo(diff, 1.0, 16) + hemisphere_albedo(diff, -1.0, 16);
}

TEST(TransmissionCompensation, WhiteGlassFurnaceWithinOnePercent) {
  BsdfOptions on;
  on.transmission_compensation = true;
  double range[3][2] = {{2, 0}, {2, 0}, {2, 0}};  // thin, volumetric outside, volumetric inside
  for (const bool thin : {true, false})
    for (double r : {0.3, 0.5, 1.0})
      for (double ior : {1.01, 1.05, 1.33, 2.0, 3.0}) {
        const MaterialBsdf b(white_glass(r, ior, thin), LutSet::builtin(), on);
        const MaterialBsdf spec(white_glass(r, ior, thin), LutSet::builtin());
        for (const bool inside : {false, true}) {
          if (thin && inside) continue;  // thin-walled: both sides are the same
          for (double mu : {0.02, 0.1, 0.4, 1.0}) {
            const double e = compensated_furnace(b, spec, mu, r, ior, thin, inside);
            double& lo = range[thin ? 0 : inside ? 2 : 1][0];
            double& hi = range[thin ? 0 : inside ? 2 : 1][1];
            lo = std::min(lo, e);
            hi = std::max(hi, e);
            EXPECT_GE(e, 0.99) << (thin ? "thin" : "volumetric") << " r " << r << " ior " << ior << " mu " << mu
                               << (inside ? " inside" : " outside");
            EXPECT_LE(e, 1.01) << (thin ? "thin" : "volumetric") << " r " << r << " ior " << ior << " mu " << mu
                               << (inside ? " inside" : " outside");
          }
        }
      }
  const char* what[] = {"thin-walled", "volumetric, outside", "volumetric, inside"};
  for (int k = 0; k < 3; ++k) std::printf("compensated white glass, %s: E in [%.4f, %.4f]\n", what[k], range[k][0], range[k][1]);
}

TEST(TransmissionCompensation, OffByDefaultAndLossWithoutIt) {
  // The spec's BSDF (the default) loses energy at r = 1: from inside at normal incidence it keeps
  // 0.42 (docs/validation.md); with the option the same material keeps 1.
  const MaterialBsdf spec(white_glass(1.0, 1.5, false));
  BsdfOptions on;
  on.transmission_compensation = true;
  const MaterialBsdf comp(white_glass(1.0, 1.5, false), LutSet::builtin(), on);
  const Vec3 v{0.0, 0.0, -1.0};
  auto albedo = [&](const Bsdf& b) {
    auto g = [&](const Vec3& l) { return b.eval(v, l).r; };
    return hemisphere_albedo(g, 1.0, 24) + hemisphere_albedo(g, -1.0, 24);
  };
  EXPECT_LT(albedo(spec), 0.6);
  EXPECT_NEAR(albedo(comp), 1.0, 0.01);
}

TEST(TransmissionCompensation, CompensatedLobesFollowTheEtaSquaredRule) {
  // The spec's M_t obeys f(v, l) / eta_l^2 = f(l, v) / eta_v^2 (docs/bsdf.md); the compensated
  // transparent core keeps that rule, and thin-walled glass stays symmetric.
  BsdfOptions on;
  on.transmission_compensation = true;
  Pcg32 rng(7, 3);
  auto dir = [&](double sign) {
    const double z = 0.05 + 0.95 * rng.next_double(), phi = 2 * kPi * rng.next_double();
    const double s = std::sqrt(1 - z * z);
    return Vec3{s * std::cos(phi), s * std::sin(phi), sign * z};
  };
  for (double ior : {1.33, 2.0}) {
    const MaterialBsdf vol(white_glass(0.6, ior, false), LutSet::builtin(), on);
    const MaterialBsdf thin(white_glass(0.6, ior, true), LutSet::builtin(), on);
    for (int i = 0; i < 200; ++i) {
      const Vec3 v = dir(1.0), l = dir(-1.0);  // v outside (eta 1), l inside (eta = ior)
      const double a = vol.eval(v, l).r / (ior * ior), b = vol.eval(l, v).r;
      EXPECT_NEAR(a, b, 1e-9 * std::max(1.0, std::abs(a)));
      EXPECT_NEAR(thin.eval(v, l).r, thin.eval(l, v).r, 1e-9 * std::max(1.0, thin.eval(v, l).r));
      const Vec3 l2 = dir(1.0);
      EXPECT_NEAR(vol.eval(v, l2).r, vol.eval(l2, v).r, 1e-9 * std::max(1.0, vol.eval(v, l2).r));
    }
  }
}

TEST(TransmissionCompensation, SceneTablesAddTheGlassTablesForVolumetricGlassOnly) {
  // scene/components.h: volumetric glass reads the four Glass tables with the option (the BSDF's
  // add_transmission_compensation); thin-walled glass only GGX_E / GGX_E_avg (docs/luts.md).
  auto has = [](const std::vector<std::string>& t, const std::string& n) {
    return std::find(t.begin(), t.end(), n) != t.end();
  };
  const auto vol = tables_for_components(kVolumetricTransparent, true);
  for (const char* n : {"Glass_E", "Glass_inv_E", "Glass_E_avg", "Glass_inv_E_avg", "GGX_E", "GGX_E_avg"})
    EXPECT_TRUE(has(vol, n)) << n;
  EXPECT_FALSE(has(tables_for_components(kVolumetricTransparent, false), "Glass_E"));
  EXPECT_FALSE(has(tables_for_components(kThinTransparent, true), "Glass_E"));
  for (const std::string& n : vol) EXPECT_TRUE(is_lut_table_name(n)) << n;  // dspbr lut --scene can make them
}

}  // namespace
}  // namespace dspbr

namespace dspbr {
namespace {

// Every stored value of a set (both layouts' tables, the glass tables included) set to NaN.
void poison(LutSet& s) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (Table* t : {&s.ggx_e, &s.ggx_e_avg, &s.base_e, &s.base_e_avg, &s.sheen_e, &s.sheen_ash_e, &s.glass_e,
                   &s.glass_inv_e, &s.glass_e_avg, &s.glass_inv_e_avg})
    std::fill(t->values.begin(), t->values.end(), nan);
  for (const auto* names : {&RendererLuts::names(), &RendererLuts::glass_names()})
    for (const char* n : *names) std::fill(s.renderer.table(n)->values.begin(), s.renderer.table(n)->values.end(), nan);
}

// Lobes own what they read (docs/bsdf.md, "Structure"): a BSDF built from a temporary table set
// (parsed from the built-in text, destroyed before any evaluation), or from a copy that is then
// overwritten with NaN and destroyed, evaluates, samples and reports pdfs bit for bit as the same
// BSDF built from the built-in set. Rough glass with the compensation (volumetric and
// thin-walled), and a plastic with sheen and clearcoat (diffuse base, multiple scattering, sheen).
TEST(TransmissionCompensation, LobesOwnWhatTheyRead) {
  BsdfOptions on;
  on.transmission_compensation = true;
  Material plastic;
  plastic.roughness = 0.4;
  plastic.sheenColor = Rgb(0.5);
  plastic.sheenRoughness = 0.3;
  plastic.clearcoat = 0.5;
  Material tinted = white_glass(0.45, 1.7, false);
  tinted.albedo = Rgb(0.9, 0.6, 0.3);
  tinted.specularTint = Rgb(0.8, 1.0, 0.9);
  const Material materials[] = {white_glass(0.6, 1.5, false), tinted, white_glass(0.7, 1.33, true), plastic};
  Pcg32 rng(5, 9);
  auto dir = [&]() {
    const double z = 2.0 * rng.next_double() - 1.0, phi = 2.0 * kPi * rng.next_double();
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return Vec3{s * std::cos(phi), s * std::sin(phi), z};
  };
  for (const LutLayout layout : {LutLayout::Renderer, LutLayout::Published})
    for (const Material& m : materials) {
      const MaterialBsdf expected(m, LutSet::of_layout(layout), on);
      const MaterialBsdf from_temporary(m, LutSet::from_text(LutSet::builtin_text(layout), "copy"), on);
      std::optional<LutSet> copy(LutSet::of_layout(layout));
      const MaterialBsdf from_poisoned(m, *copy, on);
      poison(*copy);
      copy.reset();
      int nonzero = 0;
      for (int i = 0; i < 300; ++i) {
        const Vec3 v = dir(), l = dir(), u{rng.next_double(), rng.next_double(), rng.next_double()};
        const Rgb f = expected.eval(v, l);
        nonzero += f.max_component() > 0;
        for (const MaterialBsdf* b : {&from_temporary, &from_poisoned}) {
          const Rgb g = b->eval(v, l);
          EXPECT_TRUE(g.r == f.r && g.g == f.g && g.b == f.b) << lut_layout_name(layout) << " eval " << i;
          EXPECT_EQ(b->pdf(v, l), expected.pdf(v, l)) << lut_layout_name(layout) << " pdf " << i;
          const BsdfSample s = b->sample(v, u), t = expected.sample(v, u);
          EXPECT_TRUE(s.valid == t.valid && s.l.x == t.l.x && s.l.y == t.l.y && s.l.z == t.l.z && s.pdf == t.pdf &&
                      s.weight.r == t.weight.r && s.weight.g == t.weight.g && s.weight.b == t.weight.b)
              << lut_layout_name(layout) << " sample " << i;
        }
      }
      EXPECT_GT(nonzero, 100) << lut_layout_name(layout);  // the lobes are evaluated, not skipped
    }
}

}  // namespace
}  // namespace dspbr
