// C++ cost of the shader library for one material of a glTF scene (scripts/shaders/spirv_cost.sh
// --scenes compiles it once generic and once with the scene's `dspbr shader` header): prepare +
// eval per hit, against a bare isotropic GGX reflection eval in float in the same run (the
// yardstick of bench/bench_shader.cpp). Google Benchmark; prints the two medians in ns.
//   scene_bench SCENE.gltf
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

#include "dspbr.h"
#include "dspbr/shader/gltf_factors.h"

namespace {

using namespace dspbr_shader;

DspbrMaterial g_material;
std::vector<vec3> g_v, g_l;

void directions() {
  unsigned s = 11u;  // a fixed LCG: the same 1024 pairs in every build
  auto next = [&] { s = s * 1664525u + 1013904223u; return float(s >> 8) / 16777216.0f; };
  auto dir = [&] {
    const float z = next(), phi = 6.2831853f * next(), r = std::sqrt(1.0f - z * z);
    return vec3(r * std::cos(phi), r * std::sin(phi), z);
  };
  for (int i = 0; i < 1024; ++i) g_v.push_back(dir()), g_l.push_back(dir());
}

void bare_ggx(benchmark::State& state) {
  const float a = g_material.roughness * g_material.roughness;
  const DspbrGgx g = dspbr_ggx(a, a);
  std::size_t i = 0;
  for (auto _ : state) {
    const vec3 v = g_v[i & 1023], l = g_l[i & 1023];
    const vec3 h = normalize(v + l);
    benchmark::DoNotOptimize(dspbr_ggx_M_r(g, v, l, h) * dspbr_schlick1(dot(v, h), 0.04f, 1.0f));
    ++i;
  }
}

void prepare_eval(benchmark::State& state) {
  const DspbrFrame f = dspbr_identity_frame();
  const DspbrOptions o = dspbr_default_options();
  std::size_t i = 0;
  for (auto _ : state) {
    const DspbrBsdf b = dspbr_prepare(g_material, f, o);
    benchmark::DoNotOptimize(dspbr_eval(b, g_v[i & 1023], g_l[i & 1023]));
    ++i;
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (argc != 2) {
    std::fprintf(stderr, "usage: scene_bench SCENE.gltf [--benchmark_...]\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  g_material = dspbr_material_from_gltf(dspbr::shader::gltf_factors(nlohmann::json::parse(in)["materials"][0]));
  directions();
  benchmark::RegisterBenchmark("bare_ggx", bare_ggx);
  benchmark::RegisterBenchmark("prepare_eval", prepare_eval);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
