// Eval and sample throughput of the reference BSDF (MaterialBsdf) for a plain plastic, a metal,
// a glass, a car paint (the params-2025x.json subtypes at their defaults), a plastic with a thin
// film and the full material (every component on), against a bare isotropic GGX reflection eval
// (D, height-correlated G2, Schlick F) in the same run. BM_Eval/<material> and
// BM_Sample/<material> use the component mask derived from the material (active_components);
// .../all_components evaluates every layer even at zero weight; BM_Construct/<material> builds
// the BSDF. BM_(Eval|Sample)/rough_glass_compensated: the glass at roughness 0.5 with the
// transmission-compensation option (the glass subtype is smooth). A material with flakes is built
// at 64 shading points and evaluated and sampled through them in turn, and constructed at a point
// per iteration (its flake, and whether one covers the point, depend on the point: a single point
// measured one case of each); flake_covered is the fraction of those points a flake covers.
//   dspbr_bench --benchmark_filter='BM_(Eval|Sample|Construct)/'
// Figures: docs/bsdf.md ("Speed"), docs/params.md ("Cost of inactive components").
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "dspbr/bsdf/flakes.h"
#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/fresnel.h"
#include "dspbr/ggx.h"
#include "dspbr/rng.h"
#include "dspbr/scene/components.h"
#include "bench_materials.h"

namespace {

using namespace dspbr;

const char* kNames[] = {"plastic", "metal", "glass", "carpaint", "thin_film", "full"};
constexpr int kMaterials = 6;
constexpr int kRoughGlassCompensated = kMaterials;  // not in the all_components rows

Material material(int index) {
  if (index == kRoughGlassCompensated) {
    Material m = bench::material("glass");
    m.roughness = 0.5;
    return m;
  }
  return bench::material(kNames[index]);
}

// Fixed sets of directions / random numbers (upper hemisphere for v, both for l), and the shading
// points (bench::shading_point_draws).
struct Inputs {
  std::vector<Vec3> v, l, u, p;
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
    for (const Vec3& q : bench::shading_point_draws()) p.push_back(Vec3(q.x - 0.5, q.y - 0.5, q.z - 0.5));
  }
};

const Inputs& inputs() {
  static const Inputs in;
  return in;
}

BsdfOptions options(int index, const Vec3& position) {
  BsdfOptions opt;
  opt.transmission_compensation = index == kRoughGlassCompensated;
  opt.position = position;
  return opt;
}

// The BSDFs an eval or sample benchmark goes through: at 64 shading points for a material with
// flakes, at one otherwise (every point gives the same BSDF; either count a power of two, indexed by
// a mask); the fraction covered by a flake.
std::vector<MaterialBsdf> make(benchmark::State& state, int index, bool masked) {
  const Material m = material(index);
  const uint32_t mask = masked ? active_components(m) : kAllComponents;
  const int points = m.flakeCoverage > 0 ? 64 : 1;
  std::vector<MaterialBsdf> bsdfs;
  int covered = 0;
  for (int k = 0; k < points; ++k) {
    const Vec3& p = inputs().p[std::size_t(k)];
    bsdfs.emplace_back(m, LutSet::builtin(), options(index, p), mask);
    covered += flake_at(p, Vec3(0, 0, 1), m).opacity > 0 ? 1 : 0;
  }
  state.counters["flake_covered"] = double(covered) / double(points);
  return bsdfs;
}

void eval(benchmark::State& state, int index, bool masked) {
  const std::vector<MaterialBsdf> bsdfs = make(state, index, masked);
  const std::size_t last = bsdfs.size() - 1;
  const Inputs& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bsdfs[i & last].eval(in.v[i & 1023], in.l[i & 1023]));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

void sample(benchmark::State& state, int index, bool masked) {
  const std::vector<MaterialBsdf> bsdfs = make(state, index, masked);
  const std::size_t last = bsdfs.size() - 1;
  const Inputs& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bsdfs[i & last].sample(in.v[i & 1023], in.u[i & 1023]));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

// Construction of the BSDF (lobe assembly: table slices, and the thin film's per-material tables
// of R, bsdf/thin_film_table.h).
void construct(benchmark::State& state, int index) {
  const Material m = material(index);
  const uint32_t mask = active_components(m);
  const Inputs& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    MaterialBsdf bsdf(m, LutSet::builtin(), options(index, in.p[i++ & 1023]), mask);
    benchmark::DoNotOptimize(bsdf);
  }
  state.SetItemsProcessed(state.iterations());
}

// The yardstick: f = D G2 F / (4 |v.n| |l.n|) of one isotropic GGX lobe with Schlick's F, the
// plastic's roughness, on the same directions.
void bare_ggx(benchmark::State& state) {
  const double alpha = roughness_to_alpha(bench::material("plastic").roughness);
  const GgxDistribution ggx(alpha, alpha);
  const Inputs& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    const Vec3& v = in.v[i & 1023];
    const Vec3& l = in.l[i & 1023];
    const Vec3 h = normalize(v + l);
    benchmark::DoNotOptimize(v.z > 0 && l.z > 0 ? ggx.M_r(v, l, h) * fresnel_schlick(dot(v, h), 0.04, 1.0) : 0.0);
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

[[maybe_unused]] const bool registered = [] {
  benchmark::RegisterBenchmark("BM_Eval/bare_ggx", bare_ggx);
  for (int m = 0; m < kMaterials; ++m) {
    const std::string name = kNames[m];
    benchmark::RegisterBenchmark(("BM_Eval/" + name).c_str(), eval, m, true);
    benchmark::RegisterBenchmark(("BM_Sample/" + name).c_str(), sample, m, true);
    benchmark::RegisterBenchmark(("BM_Construct/" + name).c_str(), construct, m);
  }
  benchmark::RegisterBenchmark("BM_Eval/rough_glass_compensated", eval, kRoughGlassCompensated, true);
  benchmark::RegisterBenchmark("BM_Sample/rough_glass_compensated", sample, kRoughGlassCompensated, true);
  for (int m = 0; m < kMaterials; ++m) {
    const std::string name = kNames[m];
    benchmark::RegisterBenchmark(("BM_Eval/" + name + "/all_components").c_str(), eval, m, false);
    benchmark::RegisterBenchmark(("BM_Sample/" + name + "/all_components").c_str(), sample, m, false);
  }
  return true;
}();

}  // namespace
