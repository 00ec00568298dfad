// The generated lookup code (luts/dspbr_lookup.h, .glsl, .hlsl; lutgen/lookup_codegen.h):
//  - the C header against the library's double-precision lookups (tables/renderer_luts.h) at random
//    points: within float rounding;
//  - the GLSL and HLSL files executed as C++ against GLM (their function bodies and constant
//    tables, compiled here with GLM's clamp/min/max/pow/exp/log/sqrt) against the C header.
// The shader compilers check the same files in CTest (tests/lookup_code.cmake).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/glm.hpp>

#include "../luts/dspbr_lookup.h"
#include "../luts/dspbr_glass_lookup.h"
#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/lutgen/renderer_io.h"
#include "dspbr/tables/renderer_luts.h"

// Constant tables as C++ arrays (the shader files let the includer define these).
#define DSPBR_TABLE(name, n) const float name[n] = {
#define DSPBR_TABLE_END };
namespace glsl {
using namespace glm;
#include "../luts/dspbr_lookup.glsl"
#include "../luts/dspbr_glass_lookup.glsl"
}  // namespace glsl
#undef DSPBR_LOOKUP_INCLUDED
#undef DSPBR_GLASS_LOOKUP_INCLUDED
namespace hlsl {
using namespace glm;
#include "../luts/dspbr_lookup.hlsl"
#include "../luts/dspbr_glass_lookup.hlsl"
}  // namespace hlsl

namespace {

const dspbr::RendererLuts& committed() {
  static const dspbr::RendererLuts luts =
      dspbr::read_renderer_json(DSPBR_SOURCE_DIR "/luts/dspbr_renderer_luts.json");
  return luts;
}

struct Args {
  float mu, mu2, r, f0, ab, rho;
};

std::vector<Args> random_args(int n) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<Args> out;
  for (int k = 0; k < n; ++k) {
    Args a{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    if (k % 3 == 0) a.mu = std::pow(10.0f, -4.0f * u(rng));  // grazing
    if (k % 5 == 0) a.r = std::pow(10.0f, -3.0f * u(rng));   // near the mirror
    if (k % 7 == 0) a.ab = std::pow(2.0f, -10.0f * u(rng));
    if (k == 1) a = {0, 0, 0, 0, 0, 0};  // the corners
    if (k == 2) a = {1, 1, 1, 1, 1, 1};
    out.push_back(a);
  }
  return out;
}

// |a - b| within a few float ulps of the magnitude.
void expect_float_close(double a, double b, const char* what, double tol = 2e-6) {
  EXPECT_TRUE(std::isfinite(a)) << what;
  EXPECT_NEAR(a, b, tol * std::max(1.0, std::abs(b))) << what;
}

TEST(LookupCode, CHeaderMatchesTheLibrary) {
  const dspbr::RendererLuts& L = committed();
  EXPECT_EQ(DSPBR_LOOKUP_FLOATS, int(L.stored_values()));
  for (const Args& a : random_args(2000)) {
    expect_float_close(dspbr_ggx_E(a.mu, a.r), L.E_m(a.mu, a.r), "ggx_E", 1e-5);
    // 1 - E_m from its own lookup: also relative, where 1 - dspbr_ggx_E is rounding noise (within
    // 1 %: the float cos-theta coordinate within 3e-7 of the table's end moves it by up to 0.6 %).
    const double missing = 1 - L.E_m(a.mu, a.r);
    expect_float_close(dspbr_ggx_E_missing(a.mu, a.r), missing, "ggx_E_missing", 1e-5);
    EXPECT_NEAR(dspbr_ggx_E_missing(a.mu, a.r), missing, 1e-9 + 1e-2 * missing) << a.mu << " " << a.r;
    expect_float_close(dspbr_ggx_E_avg(a.r), L.E_m_avg(a.r), "ggx_E_avg", 1e-5);
    expect_float_close(dspbr_ggx_E_avg_missing(a.r), L.missing_E_m_avg(a.r), "ggx_E_avg_missing",
                       1e-5 * L.missing_E_m_avg(a.r));
    expect_float_close(dspbr_base_E(a.mu, a.r, a.f0), L.E_base(a.mu, a.r, a.f0), "base_E", 1e-5);
    expect_float_close(dspbr_base_E_avg(a.r, a.f0), L.E_base_avg(a.r, a.f0), "base_E_avg", 1e-5);
    expect_float_close(dspbr_base_E_avg_given(a.r, a.f0, dspbr_ggx_E_avg_missing(a.r)), L.E_base_avg(a.r, a.f0),
                       "base_E_avg_given", 1e-5);
    expect_float_close(dspbr_sheen_E(a.mu, a.ab), L.E_sheen(a.mu, a.ab), "sheen_E", 1e-5);
    expect_float_close(dspbr_sheen_ash_E(a.mu, a.ab), L.E_sheen_ash(a.mu, a.ab), "sheen_ash_E", 1e-5);
  }
}

TEST(LookupCode, MissingAndBetaAtOnceAreTheTwoCallsAndTheLibrarys) {
  // dspbr_ggx_E_missing_beta shares the two lookups' coordinates and roughness taps: the same
  // values as the two calls (in every dialect), and, composed into E(mu; r, f0), the library's
  // Base_E (an independent check of beta). Also out of range and NaN, where both clamp alike.
  const dspbr::RendererLuts& L = committed();
  std::vector<Args> args = random_args(2000);
  for (float x : {-1.0f, 2.0f, NAN, INFINITY, -INFINITY}) args.push_back({x, 0.5f, x, 0.5f, 0.5f, 0.5f});
  auto same = [](float a, float b, const char* what) { expect_float_close(a, b, what, 2e-7); };
  for (const Args& a : args) {
    const DspbrGgxMissingBeta c = dspbr_ggx_E_missing_beta(a.mu, a.r);
    same(c.missing, dspbr_ggx_E_missing(a.mu, a.r), "C missing");
    same(c.beta, dspbr_ggx_beta(a.mu, a.r), "C beta");
    // The library's call site: without beta (a metal), the same 1 - E_m.
    const DspbrGgxMissingBeta m = dspbr_lut_ggx_missing_beta(a.mu, a.r, 0);
    same(m.missing, c.missing, "C missing without beta");
    EXPECT_EQ(m.beta, 0.0f);
    const glsl::DspbrGgxMissingBeta g = glsl::dspbr_ggx_E_missing_beta(a.mu, a.r);
    same(g.missing, glsl::dspbr_ggx_E_missing(a.mu, a.r), "GLSL missing");
    same(g.beta, glsl::dspbr_ggx_beta(a.mu, a.r), "GLSL beta");
    const hlsl::DspbrGgxMissingBeta h = hlsl::dspbr_ggx_E_missing_beta(a.mu, a.r);
    same(h.missing, hlsl::dspbr_ggx_E_missing(a.mu, a.r), "HLSL missing");
    same(h.beta, hlsl::dspbr_ggx_beta(a.mu, a.r), "HLSL beta");
    if (!(a.mu >= 0 && a.mu <= 1 && a.r >= 0 && a.r <= 1)) continue;
    const double em = 1.0 - c.missing, f0 = a.f0;
    const double e = f0 * em + (1 - f0) * c.beta * em + dspbr_fresnel_ms(a.f0, 1.0f, dspbr_ggx_E_avg(a.r)) * c.missing;
    expect_float_close(e, L.E_base(a.mu, a.r, a.f0), "E from the pair", 1e-5);
  }
}

TEST(LookupCode, CompensationTermsFollowTheSpecFormulas) {
  const float mv = 0.3f, ml = 0.7f, r = 0.6f, f0 = 0.04f;
  const double pi = 3.14159265358979;
  EXPECT_NEAR(dspbr_ms_lobe(mv, ml, r),
              (1 - dspbr_ggx_E(mv, r)) * (1 - dspbr_ggx_E(ml, r)) / (pi * (1 - dspbr_ggx_E_avg(r))), 1e-6);
  EXPECT_FLOAT_EQ(dspbr_ms_lobe(mv, ml, r),
                  dspbr_ggx_E_missing(mv, r) * dspbr_ggx_E_missing(ml, r) / (3.14159265f * dspbr_ggx_E_avg_missing(r)));
  EXPECT_NEAR(dspbr_diffuse_bc(mv, ml, r, f0),
              (1 - dspbr_base_E(mv, r, f0)) * (1 - dspbr_base_E(ml, r, f0)) / (pi * (1 - dspbr_base_E_avg(r, f0))),
              1e-6);
  const double fa = 20.0 / 21 * f0 + 1.0 / 21;
  EXPECT_NEAR(dspbr_fresnel_ms(f0, 1, 0.8f), fa * fa * 0.8 / (1 - fa * 0.2), 1e-7);
  EXPECT_NEAR(dspbr_sheen_layer_scale(mv, ml, 0.25f, 0.5f),
              std::min(1 - 0.5 * std::min(1.0f, dspbr_sheen_E(mv, 0.25f)), 1 - 0.5 * std::min(1.0f, dspbr_sheen_E(ml, 0.25f))),
              1e-6);
  EXPECT_NEAR(dspbr_ms_lobe(mv, ml, 0.0f), 0.0f, 1e-7);  // mirror: no missing energy (to float rounding)
}

TEST(LookupCode, GlslAndHlslComputeWhatTheCHeaderComputes) {
  for (const Args& a : random_args(2000)) {
    // The same ten calls in each dialect's namespace.
#define DSPBR_ALL_CALLS(ns)                                                                            \
  {ns dspbr_ggx_E(a.mu, a.r),                                                                          \
   ns dspbr_ggx_E_avg(a.r),                                                                            \
   ns dspbr_base_E(a.mu, a.r, a.f0),                                                                   \
   ns dspbr_base_E_avg(a.r, a.f0),                                                                     \
   ns dspbr_sheen_E(a.mu, a.ab),                                                                       \
   ns dspbr_sheen_ash_E(a.mu, a.ab),                                                                   \
   ns dspbr_ms_lobe(a.mu, a.mu2, a.r),                                                                 \
   ns dspbr_diffuse_bc(a.mu, a.mu2, a.r, a.f0),                                                        \
   ns dspbr_sheen_layer_scale(a.mu, a.mu2, a.ab, a.rho),                                               \
   ns dspbr_sheen_ash_layer_scale(a.mu, a.mu2, a.ab, a.rho)}
    const float c[] = DSPBR_ALL_CALLS(::);
    const float g[] = DSPBR_ALL_CALLS(glsl::);
    const float h[] = DSPBR_ALL_CALLS(hlsl::);
#undef DSPBR_ALL_CALLS
    for (int i = 0; i < 10; ++i) {
      expect_float_close(g[i], c[i], "glsl");
      expect_float_close(h[i], c[i], "hlsl");
    }
  }
}

// ---- The rough-glass file (beyond DSPBR 2025x) -------------------------------------------------

TEST(LookupCode, GlassHeaderMatchesTheLibrary) {
  const dspbr::RendererLuts& L = committed();
  ASSERT_TRUE(L.has_glass());
  EXPECT_EQ(DSPBR_GLASS_LOOKUP_FLOATS, int(L.glass_stored_values()));
  for (const Args& a : random_args(1000)) {
    const float ior = 1.0f + 2.0f * a.f0 * a.f0;  // dense near ior 1
    for (int in : {0, 1}) {
      expect_float_close(dspbr_glass_E(a.mu, a.r, ior, in), L.E_glass(a.mu, a.r, ior, in != 0), "glass_E", 2e-5);
      expect_float_close(dspbr_glass_E_avg(a.r, ior, in), L.E_glass_avg(a.r, ior, in != 0), "glass_E_avg", 1e-5);
    }
  }
  // Outside [1, 3] both take the nearer end (the library's +inf read ior 1's value before).
  for (int in : {0, 1})
    for (const auto& [ior, end] : {std::pair{HUGE_VAL, 3.0}, std::pair{-3.0, 1.0}, std::pair{7.0, 3.0}}) {
      EXPECT_EQ(L.E_glass(0.5, 0.3, ior, in != 0), L.E_glass(0.5, 0.3, end, in != 0)) << ior;
      EXPECT_EQ(L.E_glass_avg(0.3, ior, in != 0), L.E_glass_avg(0.3, end, in != 0)) << ior;
      expect_float_close(dspbr_glass_E(0.5f, 0.3f, float(ior), in), L.E_glass(0.5, 0.3, end, in != 0), "glass_E", 2e-5);
    }
}

dspbr::Material white_glass(float r, float ior, bool thin) {
  dspbr::Material m;
  m.transparency = 1;
  m.roughness = r;
  m.ior = ior;
  m.thinWalled = thin;
  return m;
}

TEST(LookupCode, GlassCompensationIsTheBsdfsCompensationLobes) {
  // The reference BSDF with the option minus the spec's BSDF is exactly the compensation lobes
  // (white glass: w_t rho_s = w_t rho = 1), which the generated functions give per direction pair.
  dspbr::BsdfOptions on;
  on.transmission_compensation = true;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  auto dir = [&](double sign) {
    const double z = 0.01 + 0.99 * u(rng), phi = 6.283185307179586 * u(rng), s = std::sqrt(1 - z * z);
    return dspbr::Vec3{s * std::cos(phi), s * std::sin(phi), sign * z};
  };
  for (int k = 0; k < 60; ++k) {
    const float r = float(0.05 + 0.95 * u(rng)), ior = float(1.02 + 1.98 * u(rng));
    for (const bool thin : {false, true}) {
      const dspbr::MaterialBsdf spec(white_glass(r, ior, thin));
      const dspbr::MaterialBsdf comp(white_glass(r, ior, thin), dspbr::LutSet::builtin(), on);
      for (const double sv : {1.0, -1.0})
        for (const double sl : {1.0, -1.0}) {
          if (thin && sv < 0) continue;  // thin-walled: the back side is the front side mirrored
          const dspbr::Vec3 v = dir(sv), l = dir(sl);
          const double want = comp.eval(v, l).r - spec.eval(v, l).r;
          const int inside = sv < 0 ? 1 : 0, transmission = sv * sl < 0 ? 1 : 0;
          const float mv = float(std::abs(v.z)), ml = float(std::abs(l.z));
          const float got = thin ? dspbr_thin_glass_compensation(mv, ml, r, ior, transmission)
                                 : dspbr_glass_compensation(mv, ml, r, ior, inside, transmission);
          EXPECT_NEAR(got, want, 2e-5 + 1e-4 * std::abs(want))
              << (thin ? "thin" : "volumetric") << " r " << r << " ior " << ior << " inside " << inside
              << " transmission " << transmission;
        }
    }
  }
}

TEST(LookupCode, GlassGlslAndHlslComputeWhatTheCHeaderComputes) {
  for (const Args& a : random_args(1000)) {
    const float ior = 1.0f + 2.0f * a.f0 * a.f0;
    for (int in : {0, 1}) {
#define DSPBR_GLASS_CALLS(ns)                                                                          \
  {ns dspbr_glass_E(a.mu, a.r, ior, in),                                                               \
   ns dspbr_glass_E_avg(a.r, ior, in),                                                                 \
   ns dspbr_glass_core_E(a.mu, a.r, ior, in),                                                          \
   ns dspbr_glass_transmission_share(a.r, ior, in),                                                    \
   ns dspbr_glass_compensation(a.mu, a.mu2, a.r, ior, in, 1),                                          \
   ns dspbr_glass_compensation(a.mu, a.mu2, a.r, ior, in, 0),                                          \
   ns dspbr_thin_glass_compensation(a.mu, a.mu2, a.r, ior, in)}
      const float c[] = DSPBR_GLASS_CALLS(::);
      const float g[] = DSPBR_GLASS_CALLS(glsl::);
      const float h[] = DSPBR_GLASS_CALLS(hlsl::);
#undef DSPBR_GLASS_CALLS
      for (int i = 0; i < 7; ++i) {
        expect_float_close(g[i], c[i], "glsl");
        expect_float_close(h[i], c[i], "hlsl");
      }
    }
  }
}

}  // namespace
