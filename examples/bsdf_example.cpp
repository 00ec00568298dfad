// Using the DSPBR reference BSDF as a library: build a material by its JSON parameter ids,
// evaluate f(v, l) and pdf(v, l), draw a few samples, and read the emission.
// Built by CMake as `example_bsdf_example`, or against an installed dspbr with examples/CMakeLists.txt.
#include <cstdio>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/material.h"
#include "dspbr/params/material_params.h"
#include "dspbr/rng.h"

int main() {
  using namespace dspbr;
  // A blue car paint: dielectric base, flakes under a clear coat.
  Material m;
  m.albedo = Rgb(0.05, 0.12, 0.5);
  m.roughness = 0.4;
  m.clearcoat = 1;
  m.clearcoatRoughness = 0.05;
  set_material_parameter(m, "flakeCoverage", 0.3);       // same fields, by JSON id
  set_material_parameter(m, "flakeSize", 0.1);           // mm
  set_material_parameter(m, "flakeRoughness", 0.3);
  validate_material(m);                                  // throws std::invalid_argument on bad ranges

  BsdfOptions opt;
  opt.position = {0.0123, 0.0456, 0.0};                  // object-space point (m): picks the flake
  const MaterialBsdf bsdf(m, LutSet::builtin(), opt);    // the built-in renderer-layout tables

  // Directions in the local frame (tangent +x, bitangent +y, normal +z), pointing away.
  const Vec3 v = normalize(Vec3{0.3, 0.0, 1.0});
  const Vec3 l = normalize(Vec3{-0.5, 0.2, 1.0});
  const Rgb f = bsdf.eval(v, l);                         // without the cosine
  std::printf("f(v, l)   = (%.6f, %.6f, %.6f)\n", f.r, f.g, f.b);
  std::printf("pdf(v, l) = %.6f\n", bsdf.pdf(v, l));

  // Importance sampling: weight = f |cos| / pdf (delta lobes: reflectance / probability).
  Pcg32 rng(1, 0);
  Rgb albedo(0);
  const int n = 100000;
  for (int k = 0; k < n; ++k) {
    const BsdfSample s = bsdf.sample(v, {rng.next_double(), rng.next_double(), rng.next_double()});
    if (s.valid) albedo += s.weight * (1.0 / n);
  }
  std::printf("directional albedo (%d samples) = (%.4f, %.4f, %.4f)\n", n, albedo.r, albedo.g, albedo.b);
  return 0;
}
