// Furnace-sphere pictures (validate/furnace_image.h): every pixel shows the directional albedo of
// its own view direction, compared with the eval-only estimator (validate/furnace.h) at the
// pixel's cos theta = n.z.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dspbr/frame.h"
#include "dspbr/validate/furnace.h"
#include "dspbr/validate/furnace_image.h"
#include "validate_doubles.h"

using namespace dspbr;
using namespace dspbr::testing;

TEST(ValidateFurnaceImage, EachPixelIsTheAlbedoOfItsOwnViewDirection) {
  // GGX reflection alone, alpha 1: its albedo falls by more than 0.1 from normal view to the rim,
  // so a pixel filled with another ring's value is caught.
  const GgxReflectionLobe lobe(1.0);
  const int res = 12;
  const std::size_t spp = 16384;
  const validate::RgbImage img = validate::furnace_sphere(lobe, res, spp, 7, 3);
  int inside = 0;
  double lo = 1, hi = 0;
  for (int y = 0; y < res; ++y)
    for (int x = 0; x < res; ++x) {
      const double px = (x + 0.5) / res * 2 - 1, py = 1 - (y + 0.5) / res * 2, r2 = px * px + py * py;
      const float* p = img.at(x, y);
      if (r2 >= 1) {
        EXPECT_EQ(p[1], 1.0f) << x << " " << y;  // background
        continue;
      }
      ++inside;
      const validate::AlbedoEstimate e = validate::albedo_eval(lobe, view_dir(std::sqrt(1 - r2)), 128, 11, x * res + y);
      // Sample weights G2/G1 lie in [0, 1]: the sampled estimate's sigma is at most 0.5 / sqrt(spp).
      EXPECT_NEAR(p[1], e.value.g, 4 * (0.5 / std::sqrt(double(spp)) + e.std_error.g)) << x << " " << y;
      lo = std::min(lo, double(p[1]));
      hi = std::max(hi, double(p[1]));
    }
  EXPECT_GT(inside, res * res / 2);
  EXPECT_GT(hi - lo, 0.1);  // the check above can tell rings apart
}
