// Adaptive Gauss-Kronrod quadrature of vector-valued functions, QUADPACK's QAG strategy
// (Piessens et al. 1983, "QUADPACK", sec. 2.2): the 15-point Kronrod rule with its embedded
// 7-point Gauss rule per panel (nodes and weights from Boost.Math), the panel with the largest
// error estimate bisected until the estimates add up to at most the tolerance. The estimate of a
// panel is QUADPACK's (QK15, below; max over the components) plus the errors the integrand
// states for its own values (a nested quadrature), weighted as the 15-point rule weights them.
// Deterministic: the same panels in the same order for the same integrand.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace dspbr {

template <int K>
using QuadValues = std::array<double, K>;

template <int K>
struct QuadResult {
  QuadValues<K> value{};
  double error = 0;  // estimated absolute error (max over components, summed over panels)
  int panels = 0;    // panels of the last subdivision
  long evaluations = 0;
};

// The 15 nodes on [-1, 1] with their Kronrod and (0 off the Gauss nodes) Gauss weights.
struct GaussKronrod15 {
  std::array<double, 15> x, wk, wg;
  static const GaussKronrod15& get();
};

// f(x, values, error): the K integrand values at x and the absolute error of those values (0
// for exact point values). One panel [a, b].
template <int K, class F>
QuadValues<K> gauss_kronrod_panel(F& f, double a, double b, double& error) {
  const GaussKronrod15& r = GaussKronrod15::get();
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  QuadValues<K> kr{}, ga{};
  double inner = 0;
  for (int i = 0; i < 15; ++i) {
    QuadValues<K> v{};
    double e = 0;
    f(mid + half * r.x[size_t(i)], v, e);
    for (int k = 0; k < K; ++k) {
      kr[size_t(k)] += r.wk[size_t(i)] * v[size_t(k)];
      ga[size_t(k)] += r.wg[size_t(i)] * v[size_t(k)];
    }
    inner += r.wk[size_t(i)] * e;
  }
  double worst = 0;
  for (int k = 0; k < K; ++k) {
    kr[size_t(k)] *= half;
    worst = std::max(worst, std::abs(kr[size_t(k)] - half * ga[size_t(k)]));
  }
  error = worst + std::abs(half) * inner;
  return kr;
}

// Integral of f over [breaks.front(), breaks.back()], one first panel between consecutive
// breaks (where the integrand has kinks), bisecting the worst panel while the total error
// estimate exceeds `tolerance` and fewer than `max_panels` panels exist.
template <int K, class F>
QuadResult<K> integrate_adaptive(F&& f, const std::vector<double>& breaks, double tolerance, int max_panels) {
  struct Panel {
    double a, b, error;
    QuadValues<K> value;
  };
  std::vector<Panel> panels;
  QuadResult<K> out;
  auto make = [&](double a, double b) {
    Panel p{a, b, 0, {}};
    p.value = gauss_kronrod_panel<K>(f, a, b, p.error);
    out.evaluations += 15;
    return p;
  };
  for (size_t i = 0; i + 1 < breaks.size(); ++i)
    if (breaks[i + 1] > breaks[i]) panels.push_back(make(breaks[i], breaks[i + 1]));
  while (true) {
    double total = 0;
    size_t worst = 0;
    for (size_t i = 0; i < panels.size(); ++i) {
      total += panels[i].error;
      if (panels[i].error > panels[worst].error) worst = i;
    }
    if (total <= tolerance || int(panels.size()) >= max_panels || panels.empty()) break;
    const Panel p = panels[worst];
    const double m = 0.5 * (p.a + p.b);
    if (!(m > p.a && m < p.b)) break;  // the panel cannot be split in double precision
    panels[worst] = make(p.a, m);
    panels.insert(panels.begin() + long(worst) + 1, make(m, p.b));
  }
  // Sum in panel order (left to right): the same bits for the same panels.
  for (const Panel& p : panels) {
    for (int k = 0; k < K; ++k) out.value[size_t(k)] += p.value[size_t(k)];
    out.error += p.error;
  }
  out.panels = int(panels.size());
  return out;
}

}  // namespace dspbr
