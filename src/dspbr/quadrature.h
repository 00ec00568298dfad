// Gauss-Legendre quadrature nodes and weights, used for reference integrals (exact sheen Lambda,
// test references). Independent of the Monte Carlo integrators.
#pragma once
#include <cstddef>
#include <vector>

namespace dspbr {

struct QuadratureRule {
  std::vector<double> x;  // nodes on [-1, 1]
  std::vector<double> w;  // weights, sum = 2
};

// n-point Gauss-Legendre rule (Newton iteration on P_n, double precision, n >= 1).
QuadratureRule gauss_legendre(int n);

// Composite Gauss-Legendre integral of f over [a, b] with `panels` equal panels of `order` nodes.
template <class F>
double integrate_gl(F&& f, double a, double b, int panels, const QuadratureRule& rule) {
  double sum = 0;
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    const double lo = a + p * h, half = 0.5 * h, mid = lo + half;
    for (std::size_t i = 0; i < rule.x.size(); ++i) sum += rule.w[i] * half * f(mid + half * rule.x[i]);
  }
  return sum;
}

}  // namespace dspbr
