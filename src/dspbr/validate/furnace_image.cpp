#include "dspbr/validate/furnace_image.h"

#include <OpenImageIO/imageio.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "dspbr/frame.h"
#include "dspbr/io/atomic_file.h"
#include "dspbr/validate/furnace.h"

namespace dspbr::validate {

RgbImage furnace_sphere(const Bsdf& bsdf, int res, std::size_t spp, uint64_t seed, uint64_t stream) {
  RgbImage img;
  img.width = img.height = res;
  img.pixels.assign(3 * std::size_t(res) * res, 1.0f);
  const Vec3 to_camera{0, 0, 1};
  // Pixel (x, y) has its centre at (a, b) / res with the odd integers a = 2x + 1 - res,
  // b = res - 2y - 1; its ring is k = a^2 + b^2 (exact). The tangent follows the circle around the
  // view axis, so the local view direction is (0, sin theta, cos theta) with sin^2 theta = k / res^2:
  // every pixel of a ring sees the same v. One estimate per ring, at the ring's first pixel in
  // raster order, fills the whole ring.
  auto ring = [res](int x, int y) {
    const int a = 2 * x + 1 - res, b = res - 2 * y - 1;
    return a * a + b * b;
  };
  std::map<int, std::size_t> index;          // ring -> its entry below
  std::vector<std::pair<int, int>> first;    // per ring: its first pixel
  std::vector<int> key;                      // per ring: k
  for (int y = 0; y < res; ++y)
    for (int x = 0; x < res; ++x)
      if (index.emplace(ring(x, y), first.size()).second) {
        first.push_back({x, y});
        key.push_back(ring(x, y));
      }
  std::vector<Rgb> value(first.size());
  std::vector<char> inside(first.size(), 0);
  tbb::parallel_for(std::size_t(0), first.size(), [&](std::size_t i) {
    const auto [x, y] = first[i];
    // Pixel centre on [-1, 1]^2, y up.
    const double px = (x + 0.5) / res * 2.0 - 1.0, py = 1.0 - (y + 0.5) / res * 2.0;
    const double r2 = px * px + py * py;
    if (r2 >= 1.0) return;
    const Vec3 n{px, py, std::sqrt(1.0 - r2)};
    // Tangent along the circle around the view axis (degenerate at the centre: from_normal).
    const Frame f = Frame::from_normal_tangent(n, Vec3{-py, px, 0});
    const Vec3 v = f.to_local(to_camera);
    value[i] = albedo_sampled(bsdf, v, spp, seed, (stream << 24) + uint64_t(key[i])).total.value;
    inside[i] = 1;
  });
  for (int y = 0; y < res; ++y)
    for (int x = 0; x < res; ++x) {
      const std::size_t i = index.at(ring(x, y));
      if (!inside[i]) continue;
      float* p = img.at(x, y);
      p[0] = float(value[i].r);
      p[1] = float(value[i].g);
      p[2] = float(value[i].b);
    }
  return img;
}

RgbImage hconcat(const std::vector<RgbImage>& images, int gap) {
  RgbImage out;
  if (images.empty()) return out;
  out.height = images[0].height;
  for (const RgbImage& i : images) {
    if (i.height != out.height) throw std::invalid_argument("hconcat: images of different heights");
    out.width += i.width;
  }
  out.width += gap * int(images.size() - 1);
  out.pixels.assign(3 * std::size_t(out.width) * out.height, 1.0f);
  int x0 = 0;
  for (const RgbImage& i : images) {
    for (int y = 0; y < i.height; ++y)
      for (int x = 0; x < i.width; ++x)
        for (int c = 0; c < 3; ++c) out.at(x0 + x, y)[c] = i.at(x, y)[c];
    x0 += i.width + gap;
  }
  return out;
}

namespace {
// sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1].
float srgb_encode(float x) {
  x = std::min(1.0f, std::max(0.0f, x));
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}
}  // namespace

void write_rgb_image(const std::string& path, const RgbImage& img) {
  const bool png = path.size() >= 4 && path.compare(path.size() - 4, 4, ".png") == 0;
  std::vector<float> data = img.pixels;
  if (png)
    for (float& x : data) x = srgb_encode(x);
  write_atomically(path, [&](const std::string& tmp) {
    auto out = OIIO::ImageOutput::create(tmp);
    if (!out) throw std::runtime_error("cannot create an image writer for '" + path + "': " + OIIO::geterror());
    OIIO::ImageSpec spec(img.width, img.height, 3, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    if (!png) spec.attribute("compression", "zip");
    // OIIO stamps the current time unless DateTime is set; an empty one is not written (same seed,
    // same bytes: the fifth fresh tester's pass found every EXR of two runs different).
    spec.attribute("DateTime", "");
    if (!out->open(tmp, spec)) throw std::runtime_error("cannot write '" + path + "': " + out->geterror());
    if (!out->write_image(OIIO::TypeDesc::FLOAT, data.data()))
      throw std::runtime_error("cannot write '" + path + "': " + out->geterror());
    if (!out->close()) throw std::runtime_error("cannot write '" + path + "': " + out->geterror());
  });
}

}  // namespace dspbr::validate
