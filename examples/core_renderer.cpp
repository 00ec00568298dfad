// A renderer taking the DSPBR reference BSDF alone: dspbr::core (math, the BSDF, the runtime
// tables and the built-in tables), without the table generator, the file formats, the validation
// or the fits, and without their dependencies (CTest `core_links_alone` checks this program's
// dynamic dependencies: no Ceres, OpenImageIO, TBB or glog). Sets the material's fields directly,
// evaluates and samples, and reads the renderer-layout tables.
// Exit status 1 when a white rough metal does not keep its energy: with the spec's
// multiple-scattering term its directional albedo is 1 (spec "Energy Preservation").
#include <cmath>
#include <cstdio>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/material.h"
#include "dspbr/rng.h"
#include "dspbr/tables/lut_set.h"

int main() {
  using namespace dspbr;
  Material m;  // DSPBR 2025x defaults, then the fields a renderer's material system fills
  m.albedo = Rgb(1.0);
  m.metallic = 1;
  m.roughness = 0.6;
  const LutSet& tables = LutSet::builtin();  // renderer layout, compiled in
  const MaterialBsdf bsdf(m, tables);

  const Vec3 v = normalize(Vec3{0.6, 0.0, 0.8});
  const Rgb f = bsdf.eval(v, normalize(Vec3{-0.5, 0.2, 1.0}));
  std::printf("f(v, l) = (%.6f, %.6f, %.6f)\n", f.r, f.g, f.b);
  std::printf("E_m(cos 0.8, r 0.6) = %.6f (single scattering, from the tables)\n", tables.E_m(0.8, 0.6));

  Pcg32 rng(7, 0);
  double albedo = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const BsdfSample s = bsdf.sample(v, {rng.next_double(), rng.next_double(), rng.next_double()});
    if (s.valid) albedo += s.weight.g / n;
  }
  std::printf("white rough metal, directional albedo (%d samples) = %.4f\n", n, albedo);
  // The sample weights are at most ~1.2 here: 200000 samples give a standard error below 1e-3.
  return std::abs(albedo - 1.0) < 5e-3 ? 0 : 1;
}
