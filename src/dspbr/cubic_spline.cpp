#include "dspbr/cubic_spline.h"

#include <stdexcept>

namespace dspbr {

std::vector<double> not_a_knot_cubics(const std::vector<double>& y) {
  const int n = int(y.size()) - 1;  // cells
  if (n < 3) throw std::invalid_argument("not_a_knot_cubics: need at least 3 cells");
  // Second derivatives M_i (grid step 1): M_{i-1} + 4 M_i + M_{i+1} = 6 (y_{i-1} - 2 y_i + y_{i+1})
  // for 0 < i < n; not-a-knot (the third derivative continuous at grid points 1 and n - 1):
  // M_0 = 2 M_1 - M_2, M_n = 2 M_{n-1} - M_{n-2}, which turns rows 1 and n - 1 into 6 M_i = r_i.
  std::vector<double> r(size_t(n) + 1, 0.0), m(size_t(n) + 1, 0.0);
  for (int i = 1; i < n; ++i) r[size_t(i)] = 6.0 * (y[size_t(i - 1)] - 2.0 * y[size_t(i)] + y[size_t(i + 1)]);
  m[1] = r[1] / 6.0;
  m[size_t(n - 1)] = r[size_t(n - 1)] / 6.0;
  if (n > 3) {
    // Rows 2 .. n-2: tridiagonal (1, 4, 1) with M_1 and M_{n-1} known (Thomas algorithm).
    const int k = n - 3;  // unknowns M_2 .. M_{n-2}
    std::vector<double> cp(static_cast<size_t>(k)), dp(static_cast<size_t>(k));
    for (int j = 0; j < k; ++j) {
      const int i = j + 2;
      double rhs = r[size_t(i)];
      if (i == 2) rhs -= m[1];
      if (i == n - 2) rhs -= m[size_t(n - 1)];
      const double denom = 4.0 - (j > 0 ? cp[size_t(j - 1)] : 0.0);
      cp[size_t(j)] = 1.0 / denom;
      dp[size_t(j)] = (rhs - (j > 0 ? dp[size_t(j - 1)] : 0.0)) / denom;
    }
    for (int j = k - 1; j >= 0; --j)
      m[size_t(j + 2)] = dp[size_t(j)] - (j + 1 < k ? cp[size_t(j)] * m[size_t(j + 3)] : 0.0);
  }
  m[0] = 2.0 * m[1] - m[2];
  m[size_t(n)] = 2.0 * m[size_t(n - 1)] - m[size_t(n - 2)];
  // Cell i: s(f) = (1-f) y_i + f y_{i+1} + ((1-f)^3 - (1-f)) M_i / 6 + (f^3 - f) M_{i+1} / 6.
  std::vector<double> c(4 * size_t(n));
  for (int i = 0; i < n; ++i) {
    const double y0 = y[size_t(i)], y1 = y[size_t(i + 1)], m0 = m[size_t(i)], m1 = m[size_t(i + 1)];
    double* ci = &c[4 * size_t(i)];
    ci[0] = (m1 - m0) / 6.0;
    ci[1] = 0.5 * m0;
    ci[2] = y1 - y0 - (2.0 * m0 + m1) / 6.0;
    ci[3] = y0;
  }
  return c;
}

}  // namespace dspbr
