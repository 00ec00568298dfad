// Displacement p' = p + t h_x + b h_y + n h_z against hand-computed frames.
#include <gtest/gtest.h>

#include <cmath>

#include "dspbr/bsdf/displacement.h"

using namespace dspbr;

TEST(Displacement, HandComputedFrames) {
  // Identity frame: p' = p + h.
  const Vec3 p{1.0, 2.0, 3.0};
  const Vec3 a = displaced_position(p, Frame{}, {0.1, -0.2, 0.5});
  EXPECT_DOUBLE_EQ(a.x, 1.1);
  EXPECT_DOUBLE_EQ(a.y, 1.8);
  EXPECT_DOUBLE_EQ(a.z, 3.5);
  // Surface facing +x with tangent +y: t = (0,1,0), b = n x t = (0,0,1), n = (1,0,0).
  const Frame f = Frame::from_normal_tangent({1, 0, 0}, {0, 1, 0});
  const Vec3 b = displaced_position(p, f, {0.25, 0.5, 2.0});
  EXPECT_NEAR(b.x, 3.0, 1e-15);   // n h_z
  EXPECT_NEAR(b.y, 2.25, 1e-15);  // t h_x
  EXPECT_NEAR(b.z, 3.5, 1e-15);   // b h_y
  // Any orthonormal frame preserves the displacement length and its normal component.
  const Frame g = Frame::from_normal(normalize(Vec3{0.3, -0.5, 0.8}));
  const Vec3 h{0.7, -0.1, 0.4};
  const Vec3 c = displaced_position(p, g, h);
  EXPECT_NEAR(length(c - p), length(h), 1e-15);
  EXPECT_NEAR(dot(c - p, g.n), h.z, 1e-15);
  Material m;  // default displacement (0, 0, 0): p unchanged
  const Vec3 d = displaced_position(p, g, m);
  EXPECT_EQ(d.x, p.x);
  EXPECT_EQ(d.z, p.z);
}
