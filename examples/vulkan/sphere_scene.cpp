#include "sphere_scene.h"

#include <cmath>

namespace sphere {

using dspbr::Material;
using dspbr::Rgb;
using dspbr::Vec3;

std::vector<Material> materials() {
  auto make = [](Rgb albedo, double metallic, double roughness, double specular) {
    Material m;  // DSPBR 2025x defaults (thin-walled, ior 1.5, specular tint 1), then these
    m.albedo = albedo;
    m.metallic = metallic;
    m.roughness = roughness;
    m.specular = specular;
    return m;
  };
  return {make(Rgb(0.8, 0.2, 0.1), 0, 0.5, 1),     make(Rgb(0.1, 0.3, 0.8), 0, 0.2, 1),
          make(Rgb(1.0, 0.77, 0.34), 1, 0.5, 1),   make(Rgb(0.95, 0.64, 0.54), 1, 0.2, 1),
          make(Rgb(0.5, 0.8, 0.5), 0.5, 0.35, 0.5)};
}

std::vector<float> Scene::buffer(const std::vector<Material>& mats) const {
  std::vector<float> b = {float(eye.x),   float(eye.y),   float(eye.z),   float(tan_half_fov),
                          float(light.x), float(light.y), float(light.z), float(intensity)};
  for (const Material& m : mats)
    b.insert(b.end(), {float(m.albedo.r), float(m.albedo.g), float(m.albedo.b), float(m.metallic),
                       float(m.roughness), float(m.specular), float(m.ior), 0.0f});
  return b;
}

PixelGeometry pixel_geometry(const Scene& scene, int px, int py, int tile) {
  // The primary ray through the pixel's centre, the nearer root of |eye + t d| = 1.
  const double nx = (px + 0.5) / tile * 2 - 1, ny = (py + 0.5) / tile * 2 - 1;
  const Vec3 d = normalize(Vec3{nx * scene.tan_half_fov, -ny * scene.tan_half_fov, -1.0});
  const double b = dot(scene.eye, d), disc = b * b - (dot(scene.eye, scene.eye) - 1.0);
  PixelGeometry g;
  if (disc < 0) return g;
  const Vec3 x = scene.eye - d * (b + std::sqrt(disc)), to_light = scene.light - x;
  const double d2 = dot(to_light, to_light);
  g.hit = true;
  g.n = normalize(x);
  g.v = -d;
  g.l = to_light / std::sqrt(d2);
  g.light_scale = scene.intensity / d2;
  return g;
}

}  // namespace sphere
