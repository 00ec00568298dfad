// Eval and sample throughput of the reference BSDF (MaterialBsdf) for a plain plastic, a metal,
// a glass, a car paint (the params-2025x.json subtypes at their defaults) and the full material
// (every component on), with the component mask derived from the material (active_components)
// and without it (kAllComponents: every layer evaluated even at zero weight).
//   dspbr_bench --benchmark_filter=Material
// Figures: docs/params.md ("Cost of inactive components").
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/params/material_instance.h"
#include "dspbr/params/param_defs.h"
#include "dspbr/rng.h"
#include "dspbr/scene/components.h"

namespace {

using namespace dspbr;

Material subtype(const char* id) {
  static const ParamDefs defs = default_param_defs();
  return material_from_instance(defs, nlohmann::json{{"material", id}});
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

Material material(int index) {
  switch (index) {
    case 0: return subtype("plastic");
    case 1: return subtype("metal");
    case 2: return subtype("glass");
    case 3: return subtype("carpaint");
    default: return full_material();
  }
}

const char* kNames[] = {"plastic", "metal", "glass", "carpaint", "full"};

// Fixed sets of directions / random numbers (upper hemisphere for v, both for l).
struct Inputs {
  std::vector<Vec3> v, l, u;
  Inputs() {
    Pcg32 rng(1, 0);
    for (int i = 0; i < 1024; ++i) {
      auto dir = [&](bool upper) {
        const double z = upper ? rng.next_double() * 0.98 + 0.02 : 2 * rng.next_double() - 1;
        const double phi = 2 * M_PI * rng.next_double(), s = std::sqrt(std::max(0.0, 1 - z * z));
        return Vec3(s * std::cos(phi), s * std::sin(phi), z);
      };
      v.push_back(dir(true));
      l.push_back(dir(i % 4 != 0));  // a quarter in the lower hemisphere (transmission)
      u.push_back(Vec3(rng.next_double(), rng.next_double(), rng.next_double()));
    }
  }
};

const Inputs& inputs() {
  static const Inputs in;
  return in;
}

MaterialBsdf make(const benchmark::State& state) {
  const Material m = material(static_cast<int>(state.range(0)));
  const uint32_t mask = state.range(1) ? active_components(m) : kAllComponents;
  return MaterialBsdf(m, LutSet::builtin(), BsdfOptions{}, mask);
}

void label(benchmark::State& state) {
  state.SetLabel(std::string(kNames[state.range(0)]) + (state.range(1) ? " masked" : " all-components"));
  state.SetItemsProcessed(state.iterations());
}

void BM_MaterialEval(benchmark::State& state) {
  const MaterialBsdf bsdf = make(state);
  const Inputs& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bsdf.eval(in.v[i & 1023], in.l[i & 1023]));
    ++i;
  }
  label(state);
}

void BM_MaterialSample(benchmark::State& state) {
  const MaterialBsdf bsdf = make(state);
  const Inputs& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bsdf.sample(in.v[i & 1023], in.u[i & 1023]));
    ++i;
  }
  label(state);
}

void args(benchmark::internal::Benchmark* b) {
  for (int m = 0; m < 5; ++m)
    for (int masked = 1; masked >= 0; --masked) b->Args({m, masked});
}

BENCHMARK(BM_MaterialEval)->Apply(args);
BENCHMARK(BM_MaterialSample)->Apply(args);

}  // namespace
