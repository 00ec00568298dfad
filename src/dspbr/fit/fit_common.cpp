#include "dspbr/fit/fit_common.h"

#include <algorithm>

namespace dspbr::fit {

std::vector<double> uniform_grid(double lo, double hi, int n) {
  std::vector<double> g(size_t(std::max(n, 0)));
  for (int i = 0; i < n; ++i) g[size_t(i)] = lo + (i + 0.5) / n * (hi - lo);
  return g;
}

std::vector<double> geometric_grid(double lo, double hi, int n) {
  std::vector<double> g(size_t(std::max(n, 0)));
  for (int i = 0; i < n; ++i) g[size_t(i)] = n == 1 ? lo : lo * std::pow(hi / lo, double(i) / (n - 1));
  return g;
}

std::vector<double> cosine_grid(double lo, double hi, int n, double offset) {
  // a quarter of the points (at least 2) geometric on [lo, 0.1], the rest uniform on [0.1, hi]
  std::vector<double> g;
  const double mid = std::clamp(0.1, lo, hi);
  const int ng = mid > lo ? std::max(2, n / 4) : 0, nu = n - ng;
  for (int i = 0; i < ng; ++i) g.push_back(lo * std::pow(mid / lo, (i + offset) / ng));
  for (int i = 0; i < nu; ++i) g.push_back(mid + (i + offset) / nu * (hi - mid));
  return g;
}

}  // namespace dspbr::fit
