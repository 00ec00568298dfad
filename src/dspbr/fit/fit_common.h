// Shared pieces of the fits: error statistics, evaluation grids, the
// settings every fit receives, and a parallel map that is deterministic whatever the thread count.
#pragma once
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace dspbr::fit {

// Max, RMS and mean of |error| over a set of samples.
struct ErrorStats {
  double max = 0, sum = 0, sum2 = 0;
  size_t n = 0;
  void add(double e) {
    const double a = std::abs(e);
    max = std::max(max, a);  // NaN never compares greater: record it explicitly below
    if (!(a == a)) max = HUGE_VAL;
    sum += a;
    sum2 += a * a;
    ++n;
  }
  double mean() const { return n ? sum / double(n) : 0.0; }
  double rms() const { return n ? std::sqrt(sum2 / double(n)) : 0.0; }
  nlohmann::json to_json() const { return {{"max", max}, {"rms", rms()}, {"mean", mean()}, {"samples", n}}; }
};

// Settings common to all fits.
struct FitContext {
  int threads = 0;          // 0: all cores
  uint64_t seed = 1;        // seeds the Monte Carlo/QMC reference integrals
  bool progress = false;    // progress lines on stderr
  bool quick = false;       // small grids (tests): same forms, coarser reference
  std::string command;      // the command line that produced the fit (recorded in the JSON)
};

// Evaluates f(i) for i in [0, n) in parallel into a vector (results depend only on i).
template <class T>
std::vector<T> parallel_map(const FitContext& ctx, size_t n, const std::function<T(size_t)>& f) {
  std::vector<T> out(n);
  tbb::task_arena arena(ctx.threads > 0 ? ctx.threads : tbb::task_arena::automatic);
  arena.execute([&] { tbb::parallel_for(size_t(0), n, [&](size_t i) { out[i] = f(i); }); });
  return out;
}

// Grids. Cell-centred uniform: lo + (i + 0.5)/n (hi - lo). Geometric: lo (hi/lo)^(i/(n-1)).
std::vector<double> uniform_grid(double lo, double hi, int n);
std::vector<double> geometric_grid(double lo, double hi, int n);
// Evaluation grid for cosines in [lo, hi]: geometric below 0.1, uniform above (n points in all).
std::vector<double> cosine_grid(double lo, double hi, int n, double offset = 0.5);

}  // namespace dspbr::fit
