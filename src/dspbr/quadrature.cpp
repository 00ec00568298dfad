#include "dspbr/quadrature.h"

#include <cmath>

#include "dspbr/constants.h"

namespace dspbr {

QuadratureRule gauss_legendre(int n) {
  QuadratureRule rule;
  rule.x.resize(n);
  rule.w.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));  // Tricomi initial guess
    double dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;  // Legendre recurrence
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) { p1 = x; p0 = 1; }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // recompute derivative at the converged node
    double p0 = 1, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n == 1 ? 1.0 : n * (x * p1 - p0) / (x * x - 1);
    const double w = 2.0 / ((1 - x * x) * dp * dp);
    rule.x[i] = -x;
    rule.x[n - 1 - i] = x;
    rule.w[i] = w;
    rule.w[n - 1 - i] = w;
  }
  return rule;
}

}  // namespace dspbr
