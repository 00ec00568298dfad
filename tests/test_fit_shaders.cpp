// The generated fit shaders (fits/dspbr_fits.glsl, .hlsl) executed as C++ against GLM (their
// function bodies and coefficient tables, compiled here with GLM's clamp/min/max/abs/sqrt/log/log2/
// exp) against the C++ header fits/dspbr_fits.hpp. The shader compilers check the same files in
// CTest (tests/fit_shaders.cmake).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/glm.hpp>

#include "../fits/dspbr_fits.hpp"

#define DSPBR_FIT_TABLE(name, n) const float name[n] = {
#define DSPBR_FIT_TABLE_END };
namespace glsl {
using namespace glm;
#include "../fits/dspbr_fits.glsl"
}  // namespace glsl
#undef DSPBR_FITS_INCLUDED
namespace hlsl {
using namespace glm;
#include "../fits/dspbr_fits.hlsl"
}  // namespace hlsl

namespace {

// |a - b| within float rounding of the magnitude (the shader text spells log10 as log2 * const).
void expect_close(double a, double b, const char* what) {
  EXPECT_TRUE(std::isfinite(a)) << what;
  EXPECT_NEAR(a, b, 2e-5 * std::max(1.0, std::abs(b))) << what;
}

TEST(FitShaders, GlslAndHlslComputeWhatTheHeaderComputes) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<float> u(0, 1);
  for (int k = 0; k < 2000; ++k) {
    float mu = u(rng), r = u(rng), f0 = u(rng), ab = u(rng), rf = 0.05f + 0.95f * u(rng);
    if (k % 3 == 0) mu = std::pow(10.0f, -3.0f * u(rng));  // grazing
    if (k % 5 == 0) r = std::pow(10.0f, -2.5f * u(rng));   // near the mirror
    if (k % 7 == 0) ab = std::pow(2.0f, -8.0f * u(rng));
    const float tv = 1.4f * u(rng), tl = 1.5f * u(rng), pl = 6.2831853f * u(rng);
    const float vx = std::sin(tv), vz = std::cos(tv);
    const float lx = std::sin(tl) * std::cos(pl), ly = std::sin(tl) * std::sin(pl), lz = std::cos(tl);
#define DSPBR_FIT_CALLS(ns)                                                                               \
  {ns dspbr_fit_ggx_E(mu, r),        ns dspbr_fit_ggx_E_avg(r),           ns dspbr_fit_ggx_E_loss(mu, r), \
   ns dspbr_fit_ggx_E_avg_loss(r),   ns dspbr_fit_base_E(mu, r, f0),      ns dspbr_fit_base_E_avg(r, f0), \
   ns dspbr_fit_sheen_E(mu, ab),     ns dspbr_fit_sheen_ash_E(mu, ab),    ns dspbr_fit_sheen_lambda(mu, ab), \
   ns dspbr_fit_flake_roughness(rf), ns dspbr_fit_flake_lobe(vx, 0.0f, vz, lx, ly, lz, rf)}
    const float c[] = DSPBR_FIT_CALLS(::);
    const float g[] = DSPBR_FIT_CALLS(glsl::);
    const float h[] = DSPBR_FIT_CALLS(hlsl::);
#undef DSPBR_FIT_CALLS
    for (int i = 0; i < 11; ++i) {
      if (i == 8 && mu <= 0.0f) continue;  // +inf in C++, 3e38 in the shaders
      expect_close(g[i], c[i], "glsl");
      expect_close(h[i], c[i], "hlsl");
    }
  }
}

}  // namespace
