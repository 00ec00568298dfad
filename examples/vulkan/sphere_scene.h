// The scene of the Vulkan sphere example (examples/vulkan/sphere.comp, sphere.cpp): a unit sphere
// at the origin per material, a camera on +z looking at it, a point light, as the buffer the
// shader reads (std430, vec4s only), and each pixel's geometry computed again in double on the
// CPU for the reference.
#pragma once
#include <vector>

#include "dspbr/material.h"
#include "dspbr/vec3.h"

namespace sphere {

// The materials, one tile each: a dielectric and a metal at a mid and a low roughness (energy
// compensation matters at both: B_c and M_r,ms F_ms) and a half-metallic mixture with s = 0.5.
std::vector<dspbr::Material> materials();

// The shader's Scene buffer: eye (xyz, tan of half the field of view), light (xyz, intensity I),
// then per material (rho.rgb, m), (r, s, eta, 0).
struct Scene {
  dspbr::Vec3 eye{0, 0, 3.5};
  double tan_half_fov = 0.35;
  dspbr::Vec3 light{-2.5, 3.0, 3.0};
  double intensity = 20.0;
  std::vector<float> buffer(const std::vector<dspbr::Material>& mats) const;
};

// What a pixel sees, in double: hit = false for the background.
struct PixelGeometry {
  bool hit = false;
  dspbr::Vec3 n, v, l;     // unit normal, direction to the eye, direction to the light
  double light_scale = 0;  // I / d^2
};
// Pixel (px, py) of a tile of `tile` x `tile` pixels: the shader's camera and intersection.
PixelGeometry pixel_geometry(const Scene& scene, int px, int py, int tile);

}  // namespace sphere
