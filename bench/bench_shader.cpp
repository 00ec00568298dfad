// The shader library's C++ compile (shaders/dspbr.h, float, renderer-layout tables) per hit, as a
// path tracer pays it: prepare + eval, prepare alone, eval and sample of a prepared BSDF, for the
// materials of bench_materials.h, each hit at its own shading point (a car paint's flake, and
// whether one covers the point, depend on it: a single point measured one case of the flake search
// and one side of the coverage), against a bare isotropic GGX reflection eval (D, height-correlated
// G2, Schlick F) in float in the same run; dspbr_bench_shader_fits: the same over the LUT-free fits
// (DSPBR_USE_FITS) instead of the tables; dspbr_bench_shader_null: the same with every table read
// one load (bench/null_tables/dspbr_fits.hpp), the floor under any lookup.
//   dspbr_bench --benchmark_filter='BM_Shader'
//   dspbr_bench_shader_fits
//   dspbr_bench_shader_null
// Ratios and the table: scripts/bench_ratios.py --shader [--bench build/dspbr_bench_shader_fits | _null],
// docs/renderer.md ("Cost").
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "bench_materials.h"
#include "dspbr.h"
#include "dspbr/rng.h"
#include "shader_material.h"

namespace {

using namespace dspbr_shader;

// The materials of bench_materials.h, as the shader library's (shader_test::to_shader_material).
const char* kNames[] = {"plastic", "metal", "glass", "coated_plastic", "carpaint", "thin_film", "full", "bumped_plastic"};
constexpr int kMaterials = 8;
DspbrMaterial material(int index) { return shader_test::to_shader_material(bench::material(kNames[index])); }

struct Inputs {
  std::vector<vec3> v, l, u, p;
  Inputs() {
    dspbr::Pcg32 rng(11, 0);
    auto dir = [&] {
      const float z = float(rng.next_double()), phi = float(6.283185307 * rng.next_double());
      const float s = std::sqrt(1.0f - z * z);
      return vec3(s * std::cos(phi), s * std::sin(phi), z);
    };
    for (int i = 0; i < 1024; ++i) {
      v.push_back(dir()), l.push_back(dir());
      u.push_back(vec3(float(rng.next_double()), float(rng.next_double()), float(rng.next_double())));
    }
    // The shading points (bench::shading_point_draws), in float.
    for (const dspbr::Vec3& q : bench::shading_point_draws()) p.push_back(vec3(float(q.x) - 0.5f, float(q.y) - 0.5f, float(q.z) - 0.5f));
  }
};
const Inputs& inputs() {
  static const Inputs in;
  return in;
}

void bare_ggx(benchmark::State& state) {
  const float a = material(0).roughness;
  const DspbrGgx g = dspbr_ggx(a * a, a * a);
  const Inputs& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    const vec3 v = in.v[i & 1023], l = in.l[i & 1023];
    const vec3 h = normalize(v + l);
    benchmark::DoNotOptimize(dspbr_ggx_M_r(g, v, l, h) * dspbr_schlick1(dot(v, h), 0.04f, 1.0f));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

// One thin-film reflectance R (0.4 um film of IOR 1.3 over IOR 1.5, the parameter defaults) at
// 64 angles in turn: the spectral quadrature a film costs per Fresnel factor.
void thin_film_R(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(dspbr_thin_film_reflectance(0.05f + 0.9f * float(i & 63) / 64.0f, 1.5f, 0.4f, 1.3f));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

enum class What { PrepareEval, Prepare, Eval, Sample };

void run(benchmark::State& state, int index, What what) {
  const DspbrMaterial m = material(index);
  const DspbrFrame f = dspbr_identity_frame();
  const Inputs& in = inputs();
  // The options of a hit at shading point p (object space, m).
  auto at = [](vec3 p) {
    DspbrOptions o = dspbr_default_options();
    o.position = p;
    return o;
  };
  // BSDFs prepared at 64 shading points, evaluated and sampled in turn (a car paint's flake, and
  // whether it covers the point, differs from one point to the next).
  std::vector<DspbrBsdf> prepared;
  for (int k = 0; k < 64; ++k) prepared.push_back(dspbr_prepare(m, f, at(in.p[std::size_t(k)])));
  // The fraction of the hits' points a flake covers (0 without flakes).
  int covered = 0;
  for (const vec3& p : in.p) covered += dspbr_has_lobe(dspbr_prepare(m, f, at(p)), DSPBR_LOBE_FLAKE) ? 1 : 0;
  state.counters["flake_covered"] = double(covered) / double(in.p.size());
  std::size_t i = 0;
  for (auto _ : state) {
    const vec3 v = in.v[i & 1023], l = in.l[i & 1023];
    // Each hit at its own shading point (the flakes' grid cell and search depend on it).
    const DspbrOptions o = at(in.p[i & 1023]);
    switch (what) {
      case What::PrepareEval: {
        // A textured material: one prepare per hit (the material varies), then one eval.
        const DspbrBsdf b = dspbr_prepare(m, f, o);
        benchmark::DoNotOptimize(dspbr_eval(b, v, l));
        break;
      }
      case What::Prepare: benchmark::DoNotOptimize(dspbr_prepare(m, f, o)); break;
      case What::Eval: benchmark::DoNotOptimize(dspbr_eval(prepared[i & 63], v, l)); break;
      case What::Sample: benchmark::DoNotOptimize(dspbr_sample(prepared[i & 63], v, in.u[i & 1023])); break;
    }
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

[[maybe_unused]] const bool registered = [] {
  // What prepare writes and reads per hit, in the run's context (console header, JSON "context").
  benchmark::AddCustomContext("sizeof(DspbrBsdf)", std::to_string(sizeof(DspbrBsdf)));
  benchmark::AddCustomContext("sizeof(DspbrMaterial)", std::to_string(sizeof(DspbrMaterial)));
  benchmark::RegisterBenchmark("BM_Shader/bare_ggx", bare_ggx);
  benchmark::RegisterBenchmark("BM_Shader/thin_film_R", thin_film_R);
  for (int m = 0; m < kMaterials; ++m) {
    const std::string name = kNames[m];
    benchmark::RegisterBenchmark(("BM_Shader/prepare_eval/" + name).c_str(), run, m, What::PrepareEval);
    benchmark::RegisterBenchmark(("BM_Shader/prepare/" + name).c_str(), run, m, What::Prepare);
    benchmark::RegisterBenchmark(("BM_Shader/eval/" + name).c_str(), run, m, What::Eval);
    benchmark::RegisterBenchmark(("BM_Shader/sample/" + name).c_str(), run, m, What::Sample);
  }
  return true;
}();

}  // namespace
