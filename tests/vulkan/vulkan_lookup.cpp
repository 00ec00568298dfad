// The generated GLSL lookups and fits on a real Vulkan driver (CTest vulkan_lookup_textures;
// docs/luts.md, "Using the tables in your renderer"): runs
// tests/shaders/vulkan_lookup.comp, compiled to SPIR-V by glslangValidator, on the first Vulkan
// device (Mesa's lavapipe on a machine without a GPU) at kPoints points of the whole domain, and
// compares every output with the C header (luts/dspbr_lookup.h, dspbr_glass_lookup.h) and the
// C++ fits (fits/dspbr_fits.hpp) evaluated here.
//   vulkan_lookup SHADER.spv arrays-1d         (constant arrays, built with VULKAN_LOOKUP_1D: only
//                                                the outputs of no table or the 1-D tables compared,
//                                                the others must be 0)
//   vulkan_lookup SHADER.spv arrays
//   vulkan_lookup SHADER.spv textures LUT_DIR   (LUT_DIR/renderer/NAME.exr uploaded as R32F
//                                                textures, bound as the header says)
// Exit 0: every value within tolerance; 1: a difference (the worst listed); 2: bad arguments or
// a Vulkan error; 77: no Vulkan device (CTest reports the test skipped, never passed).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "dspbr_fits.hpp"
// The glass header uses the main one's helpers.
#include "dspbr_lookup.h"
#include "dspbr_glass_lookup.h"
#include "dspbr/vulkan/vk_compute.h"

namespace {

constexpr uint32_t kOutputs = 26;  // the shader's kOutputs, in its order
constexpr uint32_t kPoints = 4096;
constexpr int kSkip = 77;

const char* const kOutputNames[kOutputs] = {
    "ggx_E", "ggx_E_avg", "ggx_E_avg_missing", "fresnel_ms", "base_E", "base_E_avg", "sheen_E", "sheen_ash_E",
    "ms_lobe", "diffuse_bc", "sheen_layer_scale", "sheen_ash_layer_scale", "glass_E(out)", "glass_E(in)",
    "glass_E_avg(out)", "glass_E_avg(in)", "glass_compensation", "thin_glass_compensation", "fit_ggx_E",
    "fit_ggx_E_avg", "fit_base_E", "fit_base_E_avg", "fit_sheen_E", "fit_sheen_ash_E", "fit_sheen_lambda",
    "fit_flake_lobe"};

// The outputs that read a table of two or three axes: left out (0) by the shader built with
// VULKAN_LOOKUP_1D (its TABLES_2D).
constexpr bool kReadsTable2d[kOutputs] = {true,  false, false, false, true,  false, true,  true,  true,
                                          true,  true,  true,  true,  true,  true,  true,  true,  true,
                                          false, false, false, false, false, false, false, false};

// The same outputs from the C header and the C++ fits, and per output its sensitivity to an ulp
// of difference in the albedos it reads: the compensation lobes are K (1 - E_v)(1 - E_l) / (1 -
// E_avg), products and quotients of differences of nearly equal floats, each E computed from the
// driver's exp / pow / sums on one side and glibc's on the other. The sensitivity is the sum of
// |d lobe / d E| over its three albedos: K (1 - E_l) / (1 - E_avg) for E_v (and likewise for E_l),
// lobe / (1 - E_avg) for E_avg. It stays non-zero where 1 - E_v is clamped to 0 on one side (E_v
// one ulp above 1) and not on the other; 0 for the other outputs.
void reference(const float q[4], float o[kOutputs], double sensitivity[kOutputs]) {
  const float cv = q[0], cl = q[1], r = q[2], s = q[3], ior = 1.0f + 2.0f * s;
  auto clamp01 = [](double x) { return std::min(std::max(x, 0.0), 1.0); };
  // K (mv + ml) / A + lobe / A, with lobe = K mv ml / A (0 when A <= 1e-9, as the lookups).
  auto lobe_sensitivity = [](double k, double mv, double ml, double a) {
    return a > 1e-9 ? k * (mv + ml) / a + k * mv * ml / (a * a) : 0.0;
  };
  const double pi = 3.14159265358979;
  for (uint32_t k = 0; k < kOutputs; ++k) sensitivity[k] = 0;
  sensitivity[8] = lobe_sensitivity(1 / pi, clamp01(1.0 - dspbr_ggx_E(cv, r)), clamp01(1.0 - dspbr_ggx_E(cl, r)),
                                    dspbr_ggx_E_avg_missing(r));
  sensitivity[9] = lobe_sensitivity(1 / pi, clamp01(1.0 - dspbr_base_E(cv, r, s)), clamp01(1.0 - dspbr_base_E(cl, r, s)),
                                    1.0 - dspbr_base_E_avg(r, s));
  sensitivity[16] = lobe_sensitivity(dspbr_glass_transmission_share(r, ior, 1) / pi,
                                     clamp01(1.0 - dspbr_glass_core_E(cv, r, ior, 1)),
                                     clamp01(1.0 - dspbr_glass_core_E(cl, r, ior, 0)), 1.0 - dspbr_glass_core_E_avg(r, ior, 0));
  // Thin glass: (1 - F_ms) on each of the three differences, transmission 0: K = (1 - x) / pi.
  const double fms = dspbr_fresnel_ms(dspbr_glass_f0(ior), 1.0f, dspbr_ggx_E_avg(r));
  const double x = 1.0 - (dspbr_glass_f0(ior) * (20.0 / 21.0) + 1.0 / 21.0);
  sensitivity[17] = (1.0 - fms) * lobe_sensitivity((1.0 - x) / pi, (1.0 - fms) * clamp01(1.0 - dspbr_ggx_E(cv, r)),
                                                   (1.0 - fms) * clamp01(1.0 - dspbr_ggx_E(cl, r)),
                                                   (1.0 - fms) * dspbr_ggx_E_avg_missing(r));
  o[0] = dspbr_ggx_E(cv, r);
  o[1] = dspbr_ggx_E_avg(r);
  o[2] = dspbr_ggx_E_avg_missing(r);
  o[3] = dspbr_fresnel_ms(s, 1.0f, cv);
  o[4] = dspbr_base_E(cv, r, s);
  o[5] = dspbr_base_E_avg(r, s);
  o[6] = dspbr_sheen_E(cv, s);
  o[7] = dspbr_sheen_ash_E(cv, s);
  o[8] = dspbr_ms_lobe(cv, cl, r);
  o[9] = dspbr_diffuse_bc(cv, cl, r, s);
  o[10] = dspbr_sheen_layer_scale(cv, cl, r, s);
  o[11] = dspbr_sheen_ash_layer_scale(cv, cl, r, s);
  o[12] = dspbr_glass_E(cv, r, ior, 0);
  o[13] = dspbr_glass_E(cv, r, ior, 1);
  o[14] = dspbr_glass_E_avg(r, ior, 0);
  o[15] = dspbr_glass_E_avg(r, ior, 1);
  o[16] = dspbr_glass_compensation(cv, cl, r, ior, 1, 1);
  o[17] = dspbr_thin_glass_compensation(cv, cl, r, ior, 0);
  o[18] = dspbr_fit_ggx_E(cv, r);
  o[19] = dspbr_fit_ggx_E_avg(r);
  o[20] = dspbr_fit_base_E(cv, r, s);
  o[21] = dspbr_fit_base_E_avg(r, s);
  o[22] = dspbr_fit_sheen_E(cv, s);
  o[23] = dspbr_fit_sheen_ash_E(cv, s);
  o[24] = dspbr_fit_sheen_lambda(cv, s);
  o[25] = dspbr_fit_flake_lobe(std::sqrt(1.0f - cv * cv), 0.0f, cv, -std::sqrt(1.0f - cl * cl), 0.0f, cl,
                               0.05f + 0.9f * s);
}

// Points over the whole domain: cosines down to 1e-3 (a quarter log-uniform towards it),
// roughness 0 and 1 included, s uniform; a fixed 64-bit LCG (the same points everywhere).
std::vector<float> make_points() {
  uint64_t state = 0x9E3779B97F4A7C15ull;
  auto u = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return float(double(state >> 40) / double(1ull << 24));
  };
  auto cosine = [&](uint32_t i) {
    const float x = u();
    return i % 4 == 0 ? std::pow(10.0f, -3.0f * x) : std::max(x, 1e-3f);
  };
  std::vector<float> p;
  for (uint32_t i = 0; i < kPoints; ++i) {
    const float r = i % 16 == 0 ? 0.0f : (i % 16 == 1 ? 1.0f : u());
    p.insert(p.end(), {cosine(i), cosine(i + 1), r, u()});
  }
  return p;
}

constexpr uint32_t kTextureBinding = 2;  // the shader's DSPBR_LOOKUP_BINDING_BASE in texture mode

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string usage = "usage: vulkan_lookup SHADER.spv arrays | SHADER.spv arrays-1d | SHADER.spv textures LUT_DIR";
    if (argc < 3) throw std::invalid_argument(usage);
    const std::string mode = argv[2];
    if (!(((mode == "arrays" || mode == "arrays-1d") && argc == 3) || (mode == "textures" && argc == 4)))
      throw std::invalid_argument(usage);
    const bool only_1d = mode == "arrays-1d";
    const std::vector<uint32_t> spirv = vk_compute::read_spirv(argv[1]);
    std::vector<vk_compute::TableImage> textures;
    if (mode == "textures") textures = vk_compute::read_lookup_textures(argv[3], true);

    vk_compute::Device vk("dspbr vulkan_lookup");
    if (!vk.has_device()) {
      std::printf("SKIPPED: no Vulkan device with a compute queue (install mesa-vulkan-drivers for lavapipe)\n");
      return kSkip;
    }
    const std::vector<float> points = make_points();
    const std::vector<float> gpu = vk.run(vk_compute::item_job(spirv, points.data(), points.size() * sizeof(float), kPoints, kOutputs,
                                                               textures, kTextureBinding, &kPoints, sizeof(kPoints)));

    // Tolerance: float evaluation on both sides, the driver's pow / exp / log within a few ulp of
    // glibc's (Vulkan allows 3 + 2 |x| ulp for exp): 5e-5 relative + 2e-6 absolute, plus for the
    // compensation lobes 4 ulp(1) times their sensitivity (above).
    const double rel = 5e-5, abs_tol = 2e-6, ulp1 = 0x1p-23;
    double worst[kOutputs] = {};
    uint32_t worst_at[kOutputs] = {}, failures = 0;
    for (uint32_t i = 0; i < kPoints; ++i) {
      float ref[kOutputs];
      double sensitivity[kOutputs];
      reference(&points[4 * i], ref, sensitivity);
      for (uint32_t k = 0; k < kOutputs; ++k) {
        const bool left_out = only_1d && kReadsTable2d[k];
        const double g = gpu[size_t(i) * kOutputs + k], c = left_out ? 0.0 : ref[k];
        const double tol = left_out ? 0.0 : abs_tol + rel * std::abs(c) + 4 * ulp1 * sensitivity[k];
        const double d = !std::isfinite(g) ? INFINITY : left_out ? (g == 0 ? 0.0 : INFINITY) : std::abs(g - c) / tol;
        if (!(d <= 1.0)) ++failures;
        if (!(d <= worst[k])) {
          worst[k] = d;
          worst_at[k] = i;
        }
      }
    }
    std::printf("device: %s, mode: %s, %u points x %u outputs, tolerance |gpu - c| <= %g + %g |c| + "
                "4 ulp(1) sensitivity\n", vk.device_name().c_str(), mode.c_str(), kPoints, kOutputs, abs_tol, rel);
    for (uint32_t k = 0; k < kOutputs; ++k) {
      const float* p = &points[4 * worst_at[k]];
      if (only_1d && kReadsTable2d[k] && worst[k] == 0) {
        std::printf("  %-24s not run in this mode (reads a 2-D or 3-D table)\n", kOutputNames[k]);
        continue;
      }
      float ref[kOutputs];
      double sensitivity[kOutputs];
      reference(p, ref, sensitivity);
      std::printf("  %-24s worst %.3g of the tolerance at (cos_v %.9g, cos_l %.9g, r %.9g, s %.9g): device %.9g, C %.9g\n",
                  kOutputNames[k], worst[k], p[0], p[1], p[2], p[3], gpu[size_t(worst_at[k]) * kOutputs + k], ref[k]);
    }
    if (failures) {
      std::printf("FAILED: %u values outside the tolerance\n", failures);
      return 1;
    }
    std::printf("PASSED: every value within the tolerance\n");
    return 0;
  } catch (const std::exception& e) {  // bad arguments, unreadable files, vk_compute::VkError
    std::fprintf(stderr, "vulkan_lookup: %s\n", e.what());
    return 2;
  }
}
