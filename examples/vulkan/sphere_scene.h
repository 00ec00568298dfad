// The scene of the Vulkan sphere example (examples/vulkan/sphere.comp, sphere.cpp): a unit sphere
// at the origin per material, a camera on +z looking at it, a point light, as the buffer the
// shader reads (std430: two vec4s, then each material's DSPBR_MATERIAL_FLOATS floats), and each
// pixel's geometry computed again in double on the CPU for the reference.
#pragma once
#include <string>
#include <vector>

#include "dspbr.h"
#include "dspbr/material.h"
#include "dspbr/vec3.h"

namespace sphere {

// One material of the validation scenes, both ways: the shader library's, from the glTF factors
// (dspbr/shader/gltf_factors.h, dspbr_material_from_gltf), and the reference's, from the project's glTF
// importer (src/dspbr/gltf).
struct SceneMaterial {
  std::string name;  // file stem, and "#i" for the i-th material of a file with several
  dspbr_shader::DspbrMaterial shader;
  dspbr::Material reference;
};
// Every material of the .gltf files of `folder` (sorted by file name).
std::vector<SceneMaterial> materials(const std::string& folder);

struct Scene {
  dspbr::Vec3 eye{0, 0, 3.5};
  double tan_half_fov = 0.35;
  dspbr::Vec3 light{-2.5, 3.0, 3.0};
  double intensity = 20.0;
  std::vector<float> buffer(const std::vector<SceneMaterial>& mats) const;
};

// The tangent hint of the shading frames (Gram-Schmidt against the normal): the x axis, never
// parallel to a normal the camera sees (those have n.z >= 1 / |eye| > 0).
const dspbr::Vec3 kTangentHint{1, 0, 0};

// What a pixel sees, in double: hit = false for the background.
struct PixelGeometry {
  bool hit = false;
  dspbr::Vec3 n, v, l;     // unit normal, direction to the eye, direction to the light
  double light_scale = 0;  // I / d^2
};
// Pixel (px, py) of a tile of `tile` x `tile` pixels: the shader's camera and intersection.
PixelGeometry pixel_geometry(const Scene& scene, int px, int py, int tile);

}  // namespace sphere
