#include <gtest/gtest.h>

#include <cmath>

#include "dspbr/quadrature.h"

using namespace dspbr;

// An n-point Gauss-Legendre rule integrates polynomials of degree 2n-1 exactly.
TEST(Quadrature, GaussLegendreExactForPolynomials) {
  for (int n : {1, 2, 5, 16, 64}) {
    const QuadratureRule r = gauss_legendre(n);
    for (int deg = 0; deg <= 2 * n - 1 && deg < 40; ++deg) {
      double I = 0;
      for (int i = 0; i < n; ++i) I += r.w[i] * std::pow(r.x[i], deg);
      const double exact = deg % 2 ? 0.0 : 2.0 / (deg + 1);
      EXPECT_NEAR(I, exact, 1e-13) << n << " " << deg;
    }
  }
}
