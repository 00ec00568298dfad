#include "bench_materials.h"

#include <stdexcept>

#include "dspbr/params/material_instance.h"
#include "dspbr/params/param_defs.h"
#include "dspbr/rng.h"

namespace bench {

using dspbr::Material;
using dspbr::Rgb;

namespace {

Material subtype(const std::string& id) {
  static const dspbr::ParamDefs defs = dspbr::default_param_defs();
  return dspbr::material_from_instance(defs, nlohmann::json{{"material", id}});
}

Material full_material() {
  Material m;
  m.albedo = Rgb(0.6, 0.3, 0.2);
  m.metallic = 0.3;
  m.roughness = 0.4;
  m.anisotropy = 0.5;
  m.translucency = 0.3;
  m.transparency = 0.3;
  m.thinFilm = 0.5;
  m.sheenColor = Rgb(0.5);
  m.flakeCoverage = 0.5;
  m.flakeSize = 0.05;
  m.flakeRoughness = 0.3;
  m.clearcoat = 0.5;
  m.clearcoatRoughness = 0.1;
  m.emissionValue = 10;
  m.thinWalled = false;
  m.abbeNumber = 40;
  m.attenuationColor = Rgb(0.8, 0.7, 0.6);
  m.attenuationDistance = 0.1;
  m.subsurfaceColor = Rgb(0.5);
  return m;
}

}  // namespace

Material material(const std::string& name) {
  if (name == "thin_film") {
    Material m = subtype("plastic");
    m.thinFilm = 1.0;  // thickness 0.4 um, film IOR 1.3: the parameter defaults
    return m;
  }
  if (name == "bumped_plastic") {
    Material m = subtype("plastic");
    m.normal = {0.1, 0.2, 1.0};  // a normal map's texel: the prepared BSDF builds its own frame
    return m;
  }
  if (name == "coated_plastic") {
    Material m = subtype("plastic");
    m.clearcoat = 1.0;
    m.clearcoatRoughness = 0.1;
    return m;
  }
  if (name == "full") return full_material();
  if (name == "plastic" || name == "metal" || name == "glass" || name == "carpaint") return subtype(name);
  throw std::invalid_argument("bench::material: no material '" + name + "'");
}

const std::vector<dspbr::Vec3>& shading_point_draws() {
  static const std::vector<dspbr::Vec3> points = [] {
    std::vector<dspbr::Vec3> p;
    dspbr::Pcg32 rng(12, 0);
    for (int i = 0; i < 1024; ++i) {
      // z drawn first: the points of the benchmarks' runs of 2026-12-07, which drew them as
      // arguments, evaluated by GCC from the last
      const double z = rng.next_double(), y = rng.next_double(), x = rng.next_double();
      p.push_back(dspbr::Vec3(x, y, z));
    }
    return p;
  }();
  return points;
}

}  // namespace bench
