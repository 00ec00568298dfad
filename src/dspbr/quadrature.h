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

// Cosine-weighted hemispherical average 2 Integral_0^1 g(mu) mu dmu of a function of cos theta,
// with geometric panels towards mu = 0 (decades 1e-9 .. 1, 8 panels of 8 Gauss-Legendre nodes
// each, one panel on [0, 1e-9]): resolves grazing features of any width down to 1e-9.
template <class G>
double cosine_average(G&& g) {
  static const QuadratureRule rule = gauss_legendre(8);
  auto f = [&](double mu) { return 2.0 * mu * g(mu); };
  double sum = integrate_gl(f, 0.0, 1e-9, 1, rule);
  for (double a = 1e-9; a < 1.0; a *= 10) sum += integrate_gl(f, a, a * 10, 8, rule);
  return sum;
}

}  // namespace dspbr
