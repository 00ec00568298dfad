// A renderer-side example of the generated lookups (CTest vulkan_sphere_example; docs/luts.md,
// "Using the tables in your renderer"): spheres under a point light shaded on the GPU by
// sphere.comp with the DSPBR core BRDF and its energy compensation (dspbr_core.glsl, the tables
// luts/renderer/*.exr uploaded as textures), written to an EXR, and compared with the reference
// BSDF (dspbr::MaterialBsdf, dspbr::core) evaluated on the CPU in double for the same pixels.
//   example_vulkan_sphere SHADER.spv LUT_DIR OUT.exr
// Exit 0: the relative errors within the bounds below; 1: above them; 2: bad arguments or a
// Vulkan error; 77: no Vulkan device (CTest reports the test skipped).
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/frame.h"
#include "dspbr/tables/lut_set.h"
#include "sphere_scene.h"
#include "vk_compute.h"

namespace {

constexpr uint32_t kTile = 128;  // pixels per side of one material's tile
constexpr int kSkip = 77;
constexpr uint32_t kTextureBinding = 2;  // sphere.comp's DSPBR_LOOKUP_BINDING_BASE

// What is compared: each channel of a pixel whose reference radiance is at least kDark times
// I / (pi d^2), the radiance of a white Lambertian sphere facing the light at its distance d
// from the centre (the background and the terminator's last pixels, where the radiance goes to 0
// with n.l, are left out).
constexpr double kDark = 1e-3;
// The bounds cover what differs between the two sides: the shader's float arithmetic (its
// geometry, the BRDF, the driver's sqrt / exp / pow) against double, and the lookups'
// Catmull-Rom interpolation of the same renderer tables in float (the reference reads the
// built-in renderer tables, the same values, in double). Measured 2026-12-04 on lavapipe
// (docs/luts.md): max 3.4e-4 (at the terminator, where n.l is a float difference of nearly
// orthogonal vectors), mean 3.3e-6 (the largest per material 1.1e-5: the low-roughness metal, whose
// M_r,ms reads 1 - E_m of order 1e-2, an ulp of E_m amplified); the bounds leave a factor 3 and 30 for
// drivers whose sqrt / exp / pow are less exact (Vulkan allows a few ulp).
constexpr double kMaxBound = 1e-3, kMeanBound = 1e-4;

void write_exr(const std::string& path, const std::vector<float>& rgba, int width, int height) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::invalid_argument("cannot write '" + path + "'");
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::FLOAT);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgba.data()) || !out->close())
    throw std::invalid_argument("cannot write '" + path + "'");
}

struct Errors {
  double max = 0, sum = 0;
  size_t count = 0;
  int worst_x = -1, worst_y = -1;
  void add(double e, int x, int y) {
    if (!(e <= max)) max = e, worst_x = x, worst_y = y;  // NaN counts as the worst
    sum += e;
    ++count;
  }
  double mean() const { return count ? sum / double(count) : 0.0; }
};

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc != 4) throw std::invalid_argument("usage: example_vulkan_sphere SHADER.spv LUT_DIR OUT.exr");
    const std::vector<uint32_t> spirv = vk_compute::read_spirv(argv[1]);
    const std::vector<vk_compute::TableImage> textures = vk_compute::read_lookup_textures(argv[2], false);
    const std::vector<dspbr::Material> mats = sphere::materials();
    const sphere::Scene scene;
    const std::vector<float> buffer = scene.buffer(mats);
    const uint32_t tiles = uint32_t(mats.size()), width = kTile * tiles, height = kTile;

    vk_compute::Device vk("dspbr vulkan sphere example");
    if (!vk.has_device()) {
      std::printf("SKIPPED: no Vulkan device with a compute queue (install mesa-vulkan-drivers for lavapipe)\n");
      return kSkip;
    }
    const uint32_t push[2] = {kTile, tiles};
    vk_compute::Job job;
    job.spirv = &spirv;
    job.input = buffer.data();
    job.input_bytes = buffer.size() * sizeof(float);
    job.output_floats = size_t(width) * height * 4;
    job.textures = &textures;
    job.texture_binding = kTextureBinding;
    job.push = push;
    job.push_bytes = sizeof(push);
    job.groups[0] = (width + 7) / 8;
    job.groups[1] = (height + 7) / 8;
    const std::vector<float> gpu = vk.run(job);
    write_exr(argv[3], gpu, int(width), int(height));

    // The reference: the same materials, the same pixels, in double.
    std::printf("device: %s; %u x %u pixels, %u materials -> %s\n", vk.device_name().c_str(), width, height, tiles,
                argv[3]);
    const double dark = kDark * scene.intensity / (M_PI * dot(scene.light, scene.light));
    std::printf("relative error per channel where the reference is >= %g (%g I / (pi d^2)):\n", dark, kDark);
    Errors all;
    size_t coverage_mismatch = 0;
    for (uint32_t k = 0; k < tiles; ++k) {
      const dspbr::MaterialBsdf bsdf(mats[k], dspbr::LutSet::builtin());
      std::vector<dspbr::Rgb> ref(size_t(kTile) * kTile, dspbr::Rgb(0));
      std::vector<bool> hit(ref.size());
      for (uint32_t y = 0; y < kTile; ++y)
        for (uint32_t x = 0; x < kTile; ++x) {
          const sphere::PixelGeometry g = sphere::pixel_geometry(scene, int(x), int(y), int(kTile));
          hit[y * kTile + x] = g.hit;
          if (!g.hit) continue;
          const dspbr::Frame frame = dspbr::Frame::from_normal(g.n);
          const dspbr::Vec3 v = frame.to_local(g.v), l = frame.to_local(g.l);
          const dspbr::Rgb L = bsdf.eval(v, l) * (std::max(l.z, 0.0) * g.light_scale);
          ref[y * kTile + x] = L;
        }
      Errors tile;
      for (uint32_t y = 0; y < kTile; ++y)
        for (uint32_t x = 0; x < kTile; ++x) {
          const float* p = &gpu[(size_t(y) * width + k * kTile + x) * 4];
          if ((p[3] > 0) != hit[y * kTile + x]) ++coverage_mismatch;
          for (int c = 0; c < 3; ++c) {
            const double r = ref[y * kTile + x][c];
            if (r < dark) continue;
            const double e = std::abs(double(p[c]) - r) / r;
            tile.add(e, int(k * kTile + x), int(y));
            all.add(e, int(k * kTile + x), int(y));
          }
        }
      const dspbr::Material& m = mats[k];
      const sphere::PixelGeometry w =
          sphere::pixel_geometry(scene, tile.worst_x - int(k * kTile), tile.worst_y, int(kTile));
      std::printf("  %u: rho (%.2f %.2f %.2f) m %.2f r %.2f s %.2f: max %.3g (pixel %d,%d: n.v %.3f, n.l %.3f), "
                  "mean %.3g over %zu\n", k, m.albedo.r, m.albedo.g, m.albedo.b, m.metallic, m.roughness, m.specular,
                  tile.max, tile.worst_x, tile.worst_y, dot(w.n, w.v), dot(w.n, w.l), tile.mean(), tile.count);
    }
    std::printf("all: max relative error %.3g (bound %g), mean %.3g (bound %g) over %zu pixel channels; "
                "%zu pixels hit on one side only\n", all.max, kMaxBound, all.mean(), kMeanBound, all.count,
                coverage_mismatch);
    const bool within = all.max <= kMaxBound && all.mean() <= kMeanBound && coverage_mismatch == 0;
    std::printf(within ? "PASSED\n" : "FAILED: above the bounds\n");
    return within ? 0 : 1;
  } catch (const std::exception& e) {  // bad arguments, unreadable files, vk_compute::VkError
    std::fprintf(stderr, "example_vulkan_sphere: %s\n", e.what());
    return 2;
  }
}
