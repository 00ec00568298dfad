// Furnace-sphere pictures (spec figures "White furnace test ..."): a unit sphere seen
// orthographically from +z under a uniform white environment of radiance 1. Each pixel shows the
// directional albedo E(v) of the BSDF for the view direction in that pixel's shading frame (normal =
// sphere normal, tangent along the circles around the view axis), so a perfectly energy-preserving
// BSDF makes the sphere vanish into the background (value 1).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dspbr/bsdf/bsdf.h"

namespace dspbr::validate {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> pixels;  // RGB interleaved, row 0 at the top
  float* at(int x, int y) { return &pixels[3 * (std::size_t(y) * width + x)]; }
  const float* at(int x, int y) const { return &pixels[3 * (std::size_t(y) * width + x)]; }
};

// res x res picture; spp BSDF samples per pixel (stratified, albedo_sampled). The pixels at one
// distance from the centre share their local view direction and so one estimate: the ring of
// pixel (x, y), k = a^2 + b^2 with a = 2x + 1 - res, b = res - 2y - 1, uses the random stream
// (stream << 24) + k. Background pixels are 1.
RgbImage furnace_sphere(const Bsdf& bsdf, int res, std::size_t spp, uint64_t seed, uint64_t stream);

// Places images side by side (equal heights), separated by `gap` background (value 1) columns.
RgbImage hconcat(const std::vector<RgbImage>& images, int gap);

// Writes an image through OpenImageIO (format from the extension): .exr as 32-bit float linear,
// .png as 8-bit sRGB-encoded (values clamped to [0, 1]). Atomic (io/atomic_file.h).
void write_rgb_image(const std::string& path, const RgbImage& img);

}  // namespace dspbr::validate
