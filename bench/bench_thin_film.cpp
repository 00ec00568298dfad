// Cost of one thin-film reflectance R(cos theta, eta_base, d, eta_film) as linear sRGB: the
// Fourier-space evaluation the BSDF uses against the reference spectral quadrature, at the
// parameter defaults (d = 0.4 um, film IOR 1.3) over a dielectric base (IOR 1.5), 1024 cosines;
// and the per-material table the BSDF reads (thin_film_table.h): one lookup, one construction.
//   dspbr_bench --benchmark_filter=ThinFilm      (figures: docs/components.md)
#include <benchmark/benchmark.h>

#include "dspbr/bsdf/thin_film.h"
#include "dspbr/bsdf/thin_film_table.h"

namespace {

using namespace dspbr;

void thin_film(benchmark::State& state, ThinFilmIntegration how) {
  benchmark::DoNotOptimize(thin_film_reflectance(0.5, 1.5, 0.4, 1.3, how));  // first-use set-up
  std::size_t i = 0;
  for (auto _ : state) {
    const double mu = 0.02 + 0.98 * double(i & 1023) / 1023.0;
    benchmark::DoNotOptimize(thin_film_reflectance(mu, 1.5, 0.4, 1.3, how));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

void table_lookup(benchmark::State& state) {
  const ThinFilmTable table(1.5, 0.4, 1.3);
  std::size_t i = 0;
  for (auto _ : state) {
    const double mu = 0.02 + 0.98 * double(i & 1023) / 1023.0;
    benchmark::DoNotOptimize(table(mu));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

void table_build(benchmark::State& state) {
  for (auto _ : state) {
    const ThinFilmTable table(1.5, 0.4, 1.3);
    benchmark::DoNotOptimize(table.cells());
  }
  state.SetItemsProcessed(state.iterations());
}

[[maybe_unused]] const bool registered = [] {
  benchmark::RegisterBenchmark("BM_ThinFilm/fourier", thin_film, ThinFilmIntegration::Fourier);
  benchmark::RegisterBenchmark("BM_ThinFilm/quadrature", thin_film, ThinFilmIntegration::Quadrature);
  benchmark::RegisterBenchmark("BM_ThinFilm/table", table_lookup);
  benchmark::RegisterBenchmark("BM_ThinFilm/table_build", table_build);
  return true;
}();

}  // namespace
