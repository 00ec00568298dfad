#include "sphere_scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "dspbr/gltf/gltf_file.h"
#include "dspbr/gltf/gltf_material.h"
#include "dspbr/shader/gltf_factors.h"

namespace sphere {

using dspbr::Vec3;

std::vector<SceneMaterial> materials(const std::string& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(folder))
    if (e.path().extension() == ".gltf") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<SceneMaterial> out;
  for (const auto& f : files) {
    std::ifstream in(f);
    const nlohmann::json doc = nlohmann::json::parse(in);
    const auto mapped = dspbr::gltf::map_materials(dspbr::gltf::read_gltf(f.string()));
    for (std::size_t i = 0; i < mapped.size(); ++i) {
      SceneMaterial m;
      m.name = f.stem().string() + (mapped.size() > 1 ? "#" + std::to_string(i) : "");
      m.shader = dspbr_shader::dspbr_material_from_gltf(dspbr::shader::gltf_factors(doc["materials"][i]));
      m.reference = mapped[i].material;
      out.push_back(m);
    }
  }
  return out;
}

std::vector<float> Scene::buffer(const std::vector<SceneMaterial>& mats) const {
  std::vector<float> b = {float(eye.x),   float(eye.y),   float(eye.z),   float(tan_half_fov),
                          float(light.x), float(light.y), float(light.z), float(intensity)};
  const std::size_t first = b.size();
  b.resize(first + mats.size() * dspbr_shader::DSPBR_MATERIAL_FLOATS);
  for (std::size_t k = 0; k < mats.size(); ++k) {
    float* rec = &b[first + k * dspbr_shader::DSPBR_MATERIAL_FLOATS];
    DSPBR_MATERIAL_PACK(mats[k].shader, rec, 0u);
  }
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
