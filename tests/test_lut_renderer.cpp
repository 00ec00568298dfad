// Renderer layout (tables/renderer_luts.h): warps and Catmull-Rom against closed forms, and the
// committed default set's lookups against independent quadrature (validate/lut_reference.h,
// deterministic Gauss-Legendre over the microfacet normal, no sampling, not the generator) on
// random points of the whole domain that are not table samples; the white furnace of a white
// metal and a white opaque dielectric built from the lookups, with the cosine averages of the
// lookups integrated by the geometric-panel rule of quadrature.h (not the generator's per-cell rule).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "dspbr/fresnel.h"
#include "dspbr/lutgen/renderer_generate.h"
#include "dspbr/lutgen/renderer_io.h"
#include "dspbr/tables/renderer_luts.h"
#include "dspbr/quadrature.h"
#include "dspbr/validate/lut_reference.h"

namespace dspbr {
namespace {

const RendererLuts& committed() {
  static const RendererLuts luts = read_renderer_json(DSPBR_SOURCE_DIR "/luts/dspbr_renderer_luts.json");
  return luts;
}

TEST(LutRendererWarp, FastFormEqualsThePowerToRounding) {
  // to_grid_fast (sqrt, or exp2(p log2 u)) against to_grid (std::pow) over each warp's domain,
  // including its ends and the clamped region outside.
  const Warp warps[] = {{WarpKind::Power, 1.0, 0.0},  {WarpKind::Power, 0.25, 1e-3}, {WarpKind::Power, 0.5, 1e-3},
                        {WarpKind::GgxCos, 0.6, 0.0}, {WarpKind::Power, 0.6, 0.0},   {WarpKind::LogRoughness, 1.0, 1e-3}};
  for (const Warp& w : warps)
    for (double alpha : {0.0, 1e-4, 0.09, 1.0})
      for (int k = -2; k <= 1002; ++k) {
        const double v = k / 1000.0;
        const double ref = w.to_grid(v, alpha);
        EXPECT_NEAR(w.to_grid_fast(v, alpha), ref, 1e-15 * ref) << w.describe() << " " << v;
      }
}

TEST(LutRendererWarp, RoundTripsAndEnds) {
  const Warp warps[] = {{WarpKind::Power, 1.0, 0.0}, {WarpKind::Power, 0.25, 1e-3}, {WarpKind::GgxCos, 0.6, 0.0},
                        {WarpKind::LogRoughness, 1.0, 1e-3}};
  for (const Warp& w : warps)
    for (double alpha : {1e-4, 0.09, 1.0})
      for (double x : {0.0, 0.1, 0.37, 0.9, 1.0}) {
        const double v = w.from_grid(x, alpha);
        EXPECT_NEAR(w.to_grid(v, alpha), x, 1e-12) << w.describe() << " alpha " << alpha;
      }
  // ggx_cos: t = mu / (mu + alpha sqrt(1 - mu^2)) by hand at mu = 0.6, alpha = 0.5: 0.6 / 1.0.
  EXPECT_NEAR((Warp{WarpKind::GgxCos, 1.0, 0.0}.to_grid(0.6, 0.5)), 0.6, 1e-15);
  EXPECT_EQ((Warp{WarpKind::GgxCos, 0.6, 0.0}.to_grid(0.3, 0.0)), 1.0);  // mirror: every mu maps to 1
  EXPECT_EQ((Warp{WarpKind::Power, 0.25, 1e-3}.to_grid(1e-4)), 0.0);     // clamped to the domain
}

TEST(LutRendererInterpolation, CatmullRomReproducesQuadraticsInsideAndLinesAtTheEnds) {
  WarpedTable t;
  t.name = "test";
  t.axes = {{"a", 9, {}}, {"b", 7, {}}};
  auto quad = [](double x, double y) { return 0.3 + 1.7 * x - 0.9 * y + 2.5 * x * y + 1.1 * x * x - 0.6 * y * y; };
  auto line = [](double x, double y) { return 0.3 + 1.7 * x - 0.9 * y + 2.5 * x * y; };
  for (auto* f : {+quad, +line}) {
    t.values.clear();
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 7; ++j) t.values.push_back(f(i / 8.0, j / 6.0));
    for (double x : {0.01, 0.2, 0.47, 0.8, 0.999})
      for (double y : {0.02, 0.3, 0.55, 0.93}) {
        // Quadratics are exact in the cells with four real samples, bilinear terms everywhere.
        const bool inner = x > 1 / 8.0 && x < 7 / 8.0 && y > 1 / 6.0 && y < 5 / 6.0;
        if (f == +quad && !inner) continue;
        EXPECT_NEAR(t.interpolate(x, y), f(x, y), 1e-12) << x << " " << y;
      }
  }
}

// Ranks 1 to 3 at every cell, the end cells included (the outside samples extended linearly): a
// line and a trilinear function are reproduced exactly; coordinates outside [0, 1] clamp.
TEST(LutRendererInterpolation, CatmullRomReproducesMultilinearFunctionsInEveryCellOfEveryRank) {
  WarpedTable line;
  line.axes = {{"a", 5, {}}};
  for (int i = 0; i < 5; ++i) line.values.push_back(0.7 - 1.3 * i / 4.0);
  WarpedTable cube;
  cube.axes = {{"a", 4, {}}, {"b", 6, {}}, {"c", 5, {}}};
  auto tri = [](double x, double y, double z) { return 0.2 + x - 0.5 * y + 0.8 * z + 1.5 * x * y - 0.7 * y * z + 0.9 * x * y * z; };
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 5; ++k) cube.values.push_back(tri(i / 3.0, j / 5.0, k / 4.0));
  const double xs[] = {-0.3, 0.0, 0.01, 0.2, 0.26, 0.4, 0.5, 0.74, 0.9, 0.999, 1.0, 1.4};
  auto c01 = [](double x) { return std::clamp(x, 0.0, 1.0); };
  for (double x : xs) {
    EXPECT_NEAR(line.interpolate(x), 0.7 - 1.3 * c01(x), 1e-14) << x;
    for (double y : xs)
      for (double z : xs) EXPECT_NEAR(cube.interpolate(x, y, z), tri(c01(x), c01(y), c01(z)), 1e-13) << x << " " << y << " " << z;
  }
  // Rank 1 and 2 on axes of 2 and 3 samples (both ends' extensions in one cell, fewer than four
  // taps) and of 4 and more (rank 2: four taps per axis, the packed sum).
  auto bi = [](double x, double y) { return 0.4 - 0.6 * x + 1.2 * y + 2.1 * x * y; };
  for (int n0 : {2, 3, 4, 7})
    for (int n1 : {2, 3, 4, 6}) {
      WarpedTable row;
      row.axes = {{"b", n1, {}}};
      WarpedTable square;
      square.axes = {{"a", n0, {}}, {"b", n1, {}}};
      for (int j = 0; j < n1; ++j) row.values.push_back(bi(0.3, j / (n1 - 1.0)));
      for (int i = 0; i < n0; ++i)
        for (int j = 0; j < n1; ++j) square.values.push_back(bi(i / (n0 - 1.0), j / (n1 - 1.0)));
      for (double x : xs) {
        EXPECT_NEAR(row.interpolate(x), bi(0.3, c01(x)), 1e-14) << n1 << " " << x;
        for (double y : xs) EXPECT_NEAR(square.interpolate(x, y), bi(c01(x), c01(y)), 1e-14) << n0 << "x" << n1 << " " << x << " " << y;
      }
    }
}

// Random points of the whole domain: half uniform, half log-uniform towards the small ends.
struct Points {
  std::vector<double> mu, r, f0, ab;
};
Points random_points(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Points p;
  for (int k = 0; k < n; ++k) {
    p.mu.push_back(k % 2 ? 1e-3 + (1 - 1e-3) * u(rng) : std::pow(10.0, -3 * u(rng)));
    p.r.push_back((k / 2) % 2 ? 0.01 + 0.99 * u(rng) : std::pow(10.0, -2 * u(rng)));
    p.f0.push_back(u(rng));
    p.ab.push_back((k / 2) % 2 ? 1 / 256.0 + (1 - 1 / 256.0) * u(rng) : std::pow(2.0, -8 * u(rng)));
  }
  return p;
}

struct ErrorStats {
  double max = 0, rms = 0;
};
template <class F>
ErrorStats stats(int n, F&& err) {
  ErrorStats s;
  for (int k = 0; k < n; ++k) {
    const double e = err(k);
    s.max = std::max(s.max, e);
    s.rms += e * e;
  }
  s.rms = std::sqrt(s.rms / n);
  return s;
}

// Relative where the value exceeds 1 (the measure docs/luts.md uses for the sheen tables).
double rel_err(double lookup, double ref) { return std::abs(lookup - ref) / std::max(1.0, std::abs(ref)); }

TEST(LutRenderer, CommittedSetMemoryWithinThePublishedSet) {
  EXPECT_LE(committed().stored_values(), 5920u);  // 32x32 + 32 + 16^3 + 16^2 + 2 * 16^2
}

TEST(LutRenderer, GgxEMatchesQuadratureOverTheWholeDomain) {
  const int n = 160;
  const Points p = random_points(n, 101);
  const ErrorStats s = stats(n, [&](int k) {
    return std::abs(committed().E_m(p.mu[k], p.r[k]) - validate::ggx_albedo_ref(p.mu[k], p.r[k], {48}).value);
  });
  RecordProperty("max", std::to_string(s.max));
  RecordProperty("rms", std::to_string(s.rms));
  EXPECT_LE(s.max, 1e-3);
  EXPECT_LE(s.rms, 1e-4);
}

TEST(LutRenderer, BaseEMatchesQuadratureOverTheWholeDomain) {
  const int n = 60;
  const Points p = random_points(n, 202);
  const ErrorStats s = stats(n, [&](int k) {
    return rel_err(committed().E_base(p.mu[k], p.r[k], p.f0[k]),
                   validate::base_albedo_ref(p.mu[k], p.r[k], p.f0[k], {16}).value);
  });
  EXPECT_LE(s.max, 2e-3);
}

TEST(LutRenderer, SheenTablesMatchQuadratureOverTheWholeDomain) {
  const int n = 200;
  const Points p = random_points(n, 303);
  for (const bool ash : {false, true}) {
    const ErrorStats s = stats(n, [&](int k) {
      const double v = ash ? committed().E_sheen_ash(p.mu[k], p.ab[k]) : committed().E_sheen(p.mu[k], p.ab[k]);
      return rel_err(v, validate::sheen_albedo_ref(p.mu[k], p.ab[k], ash, {16}).value);
    });
    EXPECT_LE(s.max, 2e-3) << (ash ? "Sheen_ash_E" : "Sheen_E");
  }
}

// The albedos near 0 are clamped (docs/luts.md "Limits"): before, the cubic gave E at f0 = 0 down
// to -3.5e-4 near cos 0.87, r 0.11 and the sheen albedos -1.3e-5.
TEST(LutRenderer, AlbedosAreNeverNegative) {
  const RendererLuts& L = committed();
  double worst = 0;
  const int n = 401;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double mu = double(i) / (n - 1), r = double(j) / (n - 1);
      for (const double v : {L.E_m(mu, r), L.beta(mu, r), L.E_base(mu, r, 0.0), L.E_sheen(mu, r), L.E_sheen_ash(mu, r)})
        worst = std::min(worst, v);
    }
  EXPECT_GE(worst, 0.0);
}

TEST(LutRenderer, AveragesMatchQuadrature) {
  for (double r : {0.02, 0.1, 0.25, 0.5, 0.77, 1.0}) {
    EXPECT_NEAR(committed().E_m_avg(r), validate::ggx_albedo_avg_ref(r, {24}).value, 2e-3) << r;
    for (double f0 : {0.0, 0.04, 0.5, 1.0})
      EXPECT_NEAR(committed().E_base_avg(r, f0), validate::base_albedo_avg_ref(r, f0, {16}).value, 2e-3)
          << r << " " << f0;
  }
}


// White metal (F = 1): M_r integrates to the exact E_m; the spec's M_r,ms lobe built from the
// lookups integrates to (1 - E^(mu)) (1 - avg(E^)) / (1 - E^_avg).
TEST(LutRenderer, WhiteMetalFurnaceFromTheLookups) {
  const RendererLuts& L = committed();
  double worst = 0;
  for (double r : {0.0, 0.003, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.7, 1.0}) {
    const double missing_avg_of_lookup = cosine_average([&](double mu) { return 1.0 - L.E_m(mu, r); });
    for (double mu : {1e-3, 3e-3, 0.01, 0.05, 0.2, 0.5, 1.0}) {
      const double e = r == 0 ? 1.0 : validate::ggx_albedo_ref(mu, r, {32}).value;
      const double missing_avg = L.missing_E_m_avg(r);
      const double ms = missing_avg > 1e-9 ? (1.0 - L.E_m(mu, r)) * missing_avg_of_lookup / missing_avg : 0.0;
      const double w = e + ms;
      worst = std::max(worst, std::abs(w - 1.0));
      EXPECT_NEAR(w, 1.0, 2e-3) << "r " << r << " mu " << mu;
    }
  }
  RecordProperty("max_deviation", std::to_string(worst));
}

// White opaque dielectric, specular 1 (f0 = 0.04): the specular layer integrates to the exact E;
// the B_c diffuse term of a white base built from the lookups to (1 - E^(mu)) (1 - avg E^) / (1 - E^_avg).
TEST(LutRenderer, WhiteDielectricFurnaceFromTheLookups) {
  const RendererLuts& L = committed();
  const double f0 = 0.04;
  for (double r : {0.02, 0.1, 0.3, 0.6, 1.0}) {
    const double missing_avg_of_lookup = cosine_average([&](double mu) { return 1.0 - L.E_base(mu, r, f0); });
    for (double mu : {1e-3, 0.01, 0.1, 0.5, 1.0}) {
      const double e = validate::base_albedo_ref(mu, r, f0, {16}).value;
      const double w = e + (1.0 - L.E_base(mu, r, f0)) * missing_avg_of_lookup / (1.0 - L.E_base_avg(r, f0));
      EXPECT_NEAR(w, 1.0, 2e-3) << "r " << r << " mu " << mu;
    }
  }
}

TEST(LutRenderer, JsonRoundTripAndBadFiles) {
  const RendererLuts& L = committed();
  EXPECT_EQ(L.ggx_E.axes[1].warp.kind, WarpKind::GgxCos);
  EXPECT_EQ(L.ggx_E_avg.encoding, Encoding::LogOneMinus);
  EXPECT_THROW(read_renderer_json(DSPBR_SOURCE_DIR "/luts/dspbr_luts.json"), std::runtime_error);  // other format
  EXPECT_THROW(read_renderer_json(DSPBR_SOURCE_DIR "/luts"), std::runtime_error);                  // a folder
  EXPECT_THROW(read_renderer_json("/nonexistent/x.json"), std::runtime_error);
}

TEST(LutRenderer, SplitSumChannelsAreTheLookups) {
  const std::vector<float> px = split_sum_pixels(committed(), 8);
  const double r = 2.5 / 8, mu = 5.5 / 8;  // row 2, column 5
  const float* p = &px[(2 * 8 + 5) * 3];
  EXPECT_FLOAT_EQ(p[0], float(committed().E_m(mu, r)));
  EXPECT_FLOAT_EQ(p[1], float(committed().B(mu, r)));
  // A - B (the f0 scale) and B: f0 (A - B) + B = f0 A + (1 - f0) B is the single-scattering E.
  EXPECT_NEAR(0.04 * (p[0] - p[1]) + p[1], committed().E_base(mu, r, 0.04) -
                  fresnel_ms(0.04, 1.0, committed().E_m_avg(r)) * (1.0 - committed().E_m(mu, r)), 1e-6);
}

}  // namespace
}  // namespace dspbr
