// The rough-glass tables and the compensated transparent core (beyond DSPBR 2025x; docs/luts.md
// "Glass tables", docs/bsdf.md "Transmission compensation"), checked against integrals computed
// another way: Gauss-Legendre quadrature of the lobes' own eval over the half vector (slope
// domain, fixed panels, no thresholds) for the tables, over the light direction (mu_l, phi) for
// the furnace of the compensated BSDF (no sampling), and the eta^2 rule of the volumetric BTDF.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/bsdf/microfacet_reflection.h"
#include "dspbr/bsdf/volumetric_transmission.h"
#include "dspbr/constants.h"
#include "dspbr/fresnel.h"
#include "dspbr/lut/albedo.h"
#include "dspbr/lut/generate.h"
#include "dspbr/lut/lut_set.h"
#include "dspbr/lut/renderer_io.h"
#include "dspbr/lut/renderer_luts.h"
#include "dspbr/material.h"
#include "dspbr/quadrature.h"
#include "dspbr/rng.h"
#include "dspbr/scene/components.h"
#include "test_lut_reference.h"

namespace dspbr {
namespace {

// Integral of g(l) |l.z| over one hemisphere (sign +1 upper, -1 lower) in (mu_l, phi), for v in
// the xz plane (g even in phi: [0, pi] counted twice). The mu axis is graded towards the horizon.
template <class G>
double hemisphere_albedo(G&& g, double sign, int panels) {
  static const QuadratureRule rule = gauss_legendre(8);
  return 2.0 * integrate_gl(
                   [&](double t) {
                     const double mu = t * t, s = std::sqrt(std::max(0.0, 1.0 - mu * mu));  // dmu = 2t dt
                     return 2.0 * t * integrate_gl(
                                          [&](double phi) {
                                            const Vec3 l{s * std::cos(phi), s * std::sin(phi), sign * mu};
                                            return g(l) * mu;
                                          },
                                          0.0, kPi, panels, rule);
                   },
                   0.0, 1.0, panels, rule);
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
        const double vh = dot(v, h);
        if (vh <= 0) return 0.0;
        const double dh = GgxDistribution(alpha, alpha).D(h) * h.z;
        double sum = 0;
        const Vec3 lr = reflect(v, h);
        if (lr.z > 0) sum += refl.eval(v, lr).r * lr.z * 4.0 * vh / dh;
        Vec3 lt;
        if (refract_dir(v, h, eta_i / eta_o, lt) && lt.z < 0) {
          const double lh = dot(lt, h), den = eta_i * vh + eta_o * lh;
          sum += trans.eval(v, lt).r * -lt.z * den * den / (eta_o * eta_o * std::abs(lh)) / dh;
        }
        return sum;
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
  const double sharp = lutref::ggx_half_vector_integral(
      alpha,
      [&](const Vec3& h) {
        const double vh = dot(v, h);
        if (vh <= 0) return 0.0;
        const double dh = GgxDistribution(alpha, alpha).D(h) * h.z;
        double sum = 0;
        const Vec3 lr = reflect(v, h);
        if (lr.z > 0) sum += eval(off, v, lr) * lr.z * 4.0 * vh / dh;
        if (thin) {
          if (lr.z > 0) sum += eval(off, v, Vec3{lr.x, lr.y, -lr.z}) * lr.z * 4.0 * vh / dh;
        } else {
          Vec3 lt;
          if (refract_dir(v, h, eta_i / eta_o, lt) && lt.z < 0) {
            const double lh = dot(lt, h), den = eta_i * vh + eta_o * lh;
            sum += eval(off, v, lt) * -lt.z * den * den / (eta_o * eta_o * std::abs(lh)) / dh;
          }
        }
        return sum;
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
