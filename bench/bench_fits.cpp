// ns/eval of the generated LUT-free fits (fits/dspbr_fits.hpp, float) against table lookups:
// the library's Table::lookup (double, generic N-D) and a plain float bilinear lookup on the same
// 32x32 GGX_E table with clamp-to-edge, i.e. what a shader's texture fetch computes in ALU.
// Run: ./dspbr_bench --benchmark_filter=Fit   (figures go to docs/fits.md, never into tests).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../fits/dspbr_fits.hpp"
#include "../luts/dspbr_lookup.h"
#include "dspbr/tables/albedo_slice.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/rng.h"

namespace {

struct Inputs {
  std::vector<float> mu, r;
  Inputs() {
    dspbr::Pcg32 rng(7, 0);
    for (int i = 0; i < 1024; ++i) {
      mu.push_back(float(rng.next_double()));
      r.push_back(float(rng.next_double()));
    }
  }
};
const Inputs& inputs() {
  static const Inputs in;
  return in;
}

// Float bilinear lookup on a cell-centred n x n table (rows: roughness, columns: cos theta).
struct BilinearTable {
  int n = 0;
  std::vector<float> v;
  float lookup(float mu, float r) const {
    const float x = std::clamp(mu * n - 0.5f, 0.0f, float(n - 1)), y = std::clamp(r * n - 0.5f, 0.0f, float(n - 1));
    const int x0 = std::min(int(x), n - 2), y0 = std::min(int(y), n - 2);
    const float fx = x - float(x0), fy = y - float(y0);
    const float* row0 = &v[size_t(y0 * n)];
    const float* row1 = row0 + n;
    const float a = row0[x0] + fx * (row0[x0 + 1] - row0[x0]);
    const float b = row1[x0] + fx * (row1[x0 + 1] - row1[x0]);
    return a + fy * (b - a);
  }
};

void BM_FitGgxE(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(dspbr_fit_ggx_E(in.mu[i], in.r[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_FitGgxE);

void BM_FitBaseE(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(dspbr_fit_base_E(in.mu[i], in.r[i], 0.04f));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_FitBaseE);

void BM_FitSheenE(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(dspbr_fit_sheen_E(in.mu[i], in.r[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_FitSheenE);

void BM_FitGgxEAvg(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(dspbr_fit_ggx_E_avg(in.r[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_FitGgxEAvg);

void BM_FitSheenAshE(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(dspbr_fit_sheen_ash_E(in.mu[i], in.r[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_FitSheenAshE);

// The far-field flake lobe: v at the angle acos(mu), l near its mirror direction.
void BM_FitFlakeLobe(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) {
      const float c = 0.2f + 0.8f * in.mu[i], s = std::sqrt(1.0f - c * c);
      benchmark::DoNotOptimize(dspbr_fit_flake_lobe(s, 0.0f, c, -s + 0.05f * in.r[i], 0.03f, c, 0.05f + 0.95f * in.r[i]));
    }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_FitFlakeLobe);

void BM_FitSheenLambda(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(dspbr_fit_sheen_lambda(in.mu[i], in.r[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_FitSheenLambda);

void BM_FitLutBilinearFloat(benchmark::State& state) {
  const Inputs& in = inputs();
  const dspbr::Table& t = dspbr::LutSet::published().ggx_e;
  BilinearTable b;
  b.n = t.axes[1].size;
  for (double x : t.values) b.v.push_back(float(x));
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(b.lookup(in.mu[i], in.r[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_FitLutBilinearFloat);

// LutSet lookups (double) of the published and the renderer layout, and the generated C lookup
// (float, luts/dspbr_lookup.h) that a renderer compiles.
void BM_FitLutTableLookup(benchmark::State& state) {
  const Inputs& in = inputs();
  const dspbr::LutSet& lut = state.range(0) ? dspbr::LutSet::builtin() : dspbr::LutSet::published();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(lut.E_m(in.mu[i], in.r[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
  state.SetLabel(state.range(0) ? "renderer" : "published");
}
BENCHMARK(BM_FitLutTableLookup)->Arg(0)->Arg(1);

// The lookup a lobe makes per evaluation: E_m(mu) of a slice cut at roughness 0.5 when the lobe is
// built (tables/albedo_slice.h), published or renderer layout.
void BM_SliceLookup(benchmark::State& state) {
  const Inputs& in = inputs();
  const dspbr::AlbedoSlice slice =
      dspbr::AlbedoSlice::E_m(state.range(0) ? dspbr::LutSet::builtin() : dspbr::LutSet::published(), 0.5);
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(slice(in.mu[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
  state.SetLabel(state.range(0) ? "renderer" : "published");
}
BENCHMARK(BM_SliceLookup)->Arg(0)->Arg(1);

// The same two cosines at a time, as a lobe reads v.n and l.n (AlbedoSlice::e_m_parts: the
// renderer layout's warp of both in one packed square root and division); items: lookups.
void BM_SliceLookupPair(benchmark::State& state) {
  const Inputs& in = inputs();
  const dspbr::AlbedoSlice slice = dspbr::AlbedoSlice::E_m(dspbr::LutSet::builtin(), 0.5);
  for (auto _ : state)
    for (size_t i = 0; i + 1 < in.mu.size(); i += 2) {
      dspbr::AlbedoSlice::EmPart part[2];
      slice.e_m_parts(in.mu[i], in.mu[i + 1], part);
      benchmark::DoNotOptimize(part);
    }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
  state.SetLabel("renderer");
}
BENCHMARK(BM_SliceLookupPair);

// The renderer layout's cos coordinate alone: the ggx_cos warp of power 1/2 (two square roots and a
// division) at alpha = 0.25, one cosine at a time (Warp::to_grid_fast) and two at a time
// (ggx_cos_sqrt_warp2); items: cosines.
void BM_WarpGgxCos(benchmark::State& state) {
  const Inputs& in = inputs();
  const dspbr::Warp w{dspbr::WarpKind::GgxCos, 0.5, 0.0};
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(w.to_grid_fast(in.mu[i], 0.25));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_WarpGgxCos);

void BM_WarpGgxCosPair(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i + 1 < in.mu.size(); i += 2) {
      double x[2];
      dspbr::ggx_cos_sqrt_warp2(in.mu[i], in.mu[i + 1], 0.25, x);
      benchmark::DoNotOptimize(x);
    }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_WarpGgxCosPair);

void BM_LookupGeneratedC(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(dspbr_ggx_E(in.mu[i], in.r[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_LookupGeneratedC);

// What a dielectric base reads per direction: 1 - E_m and beta, as two calls and as the one call
// that computes their coordinates and roughness taps once.
void BM_LookupGeneratedMissingBeta(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) {
      benchmark::DoNotOptimize(dspbr_ggx_E_missing(in.mu[i], in.r[i]));
      benchmark::DoNotOptimize(dspbr_ggx_beta(in.mu[i], in.r[i]));
    }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_LookupGeneratedMissingBeta);
void BM_LookupGeneratedMissingBetaPair(benchmark::State& state) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (size_t i = 0; i < in.mu.size(); ++i) benchmark::DoNotOptimize(dspbr_ggx_E_missing_beta(in.mu[i], in.r[i]));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.mu.size()));
}
BENCHMARK(BM_LookupGeneratedMissingBetaPair);

}  // namespace
