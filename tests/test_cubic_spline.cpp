// The not-a-knot cubic spline against closed forms: exact on cubic polynomials (de Boor ch. IV),
// interpolates its samples, and converges like h^4 on a smooth function up to the ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dspbr/cubic_spline.h"

using namespace dspbr;

namespace {

// Max |spline - f| over 16 points per cell of n cells on [0, 1] (grid point i at x = i / n).
template <class F>
double max_error(F f, int n) {
  std::vector<double> y(size_t(n) + 1);
  for (int i = 0; i <= n; ++i) y[size_t(i)] = f(double(i) / n);
  const std::vector<double> c = not_a_knot_cubics(y);
  double err = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= 16; ++j) {
      const double fr = j / 16.0;
      err = std::max(err, std::abs(cubic_at(&c[4 * size_t(i)], fr) - f((i + fr) / n)));
    }
  return err;
}

}  // namespace

TEST(CubicSpline, ExactOnCubics) {
  auto p = [](double x) { return 0.3 - 1.7 * x + 2.5 * x * x - 4.1 * x * x * x; };
  for (int n : {3, 4, 5, 17}) EXPECT_LT(max_error(p, n), 1e-13) << n;
}

TEST(CubicSpline, FourthOrderUpToTheEnds) {
  auto f = [](double x) { return std::sin(5 * x) * std::exp(x); };
  const double e16 = max_error(f, 16), e32 = max_error(f, 32), e64 = max_error(f, 64);
  EXPECT_GT(e16 / e32, 12.0);  // 16 for O(h^4)
  EXPECT_GT(e32 / e64, 12.0);
  EXPECT_LT(e64, 1e-5);
  EXPECT_THROW(not_a_knot_cubics({0.0, 1.0, 2.0}), std::invalid_argument);
}
