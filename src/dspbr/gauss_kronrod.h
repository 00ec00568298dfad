// Adaptive Gauss-Kronrod quadrature of vector-valued functions, QUADPACK's QAG strategy
// (Piessens et al. 1983, "QUADPACK", sec. 2.2): the 15-point Kronrod rule with its embedded
// 7-point Gauss rule per panel (nodes and weights from Boost.Math), the panel with the largest
// error estimate bisected until the estimates add up to at most the tolerance. The estimate of a
// panel is |K15 - G7| (QK15, below; max over the components) plus, where the nested errors
// steer (the default), the errors the integrand states for its own values (a nested quadrature),
// weighted as the 15-point rule weights them. Without steering they are added to the stated
// error only: bisecting a panel does not shrink them, so a caller that bounds them itself (the
// cosine averages: their sum is at most the nested tolerance times the integral of the weight)
// gives this level only its own share. The directional glass quadrature keeps the steering: its
// extra bisections where the polar integrals state large errors keep a grazing, low-roughness
// cell within 1e-6 (without it, ior 1.68, r 0.067, mu 2.6e-4 was 1.3e-6 off at 14x its stated
// error; measured 2026-12-04 against a 1e-10 run of the same quadrature, docs/design/luts.md "Speed").
// Deterministic: the same panels in the same order for the same integrand.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory_resource>
#include <type_traits>
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

// The N = 2n + 1 nodes on [-1, 1] of the N-point Kronrod rule with their Kronrod and (0 off the
// Gauss nodes) n-point Gauss weights; N = 15 (QK15, the default) or 31 (QK31, for integrands
// that cost a nested quadrature each: its higher degree needs fewer of them on smooth pieces).
template <int N>
struct GaussKronrod {
  std::array<double, N> x, wk, wg;
  static const GaussKronrod& get();
};
extern template struct GaussKronrod<15>;
extern template struct GaussKronrod<31>;

// f(x, values, error): the K integrand values at x and the absolute error of those values (0
// for exact point values). An integrand may instead take a panel's N nodes at once,
// f(mid, half, values, errors) with std::array arguments, the nodes being mid + half x_i with
// x_i = GaussKronrod<N>::get().x[i], so that it can compute them and evaluate itself in one
// vectorisable loop (the directional glass integrand). Handing it the nodes in an array instead
// cost 11% of a glass cell's time: written one at a time here and read four at a time there,
// they stall the load (store forwarding fails; measured with perf, 2026-12-04). The sums are the
// same either way.
template <int K, int N, class F>
void evaluate_nodes(F& f, double mid, double half, std::array<QuadValues<K>, N>& v, std::array<double, N>& e) {
  if constexpr (std::is_invocable_v<F&, double, double, std::array<QuadValues<K>, N>&, std::array<double, N>&>) {
    f(mid, half, v, e);
  } else {
    const GaussKronrod<N>& r = GaussKronrod<N>::get();
    for (size_t i = 0; i < size_t(N); ++i) {
      v[i] = {};
      e[i] = 0;
      f(mid + half * r.x[i], v[i], e[i]);
    }
  }
}

// One panel [a, b]: `error` is the rule's own estimate, `nested` the integrand's stated errors
// integrated.
template <int K, int N = 15, class F>
QuadValues<K> gauss_kronrod_panel(F& f, double a, double b, double& error, double& nested) {
  const GaussKronrod<N>& r = GaussKronrod<N>::get();
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  std::array<double, N> es;
  std::array<QuadValues<K>, N> vs;
  evaluate_nodes<K, N>(f, mid, half, vs, es);
  QuadValues<K> kr{}, ga{};
  double inner = 0;
  for (size_t i = 0; i < size_t(N); ++i) {
    for (size_t k = 0; k < size_t(K); ++k) {
      kr[k] += r.wk[i] * vs[i][k];
      ga[k] += r.wg[i] * vs[i][k];
    }
    inner += r.wk[i] * es[i];
  }
  double worst = 0;
  for (int k = 0; k < K; ++k) {
    kr[size_t(k)] *= half;
    worst = std::max(worst, std::abs(kr[size_t(k)] - half * ga[size_t(k)]));
  }
  error = worst;
  nested = std::abs(half) * inner;
  return kr;
}

// Integral of f over [breaks.front(), breaks.back()], one first panel between consecutive
// breaks (where the integrand has kinks), bisecting the panel of the largest estimate (its own,
// plus the integrand's stated errors when nested_steers) while their sum exceeds `tolerance` and
// fewer than `max_panels` panels exist. The error returned is the own estimates' sum plus the
// integrand's stated errors integrated.
template <int K, int N = 15, class F>
QuadResult<K> integrate_adaptive(F&& f, const std::vector<double>& breaks, double tolerance, int max_panels,
                                 bool nested_steers = true) {
  struct Panel {
    double a, b, error, nested;
    QuadValues<K> value;
  };
  // The first kInline panels live on the stack: an azimuth piece of the directional quadrature
  // usually needs one to three, and allocating them on the heap cost 10% of a glass cell
  // (measured 2026-12-04). More spill to the heap.
  constexpr size_t kInline = 16;
  alignas(Panel) std::array<std::byte, kInline * sizeof(Panel)> buffer;
  std::pmr::monotonic_buffer_resource arena(buffer.data(), buffer.size());
  std::pmr::vector<Panel> panels(&arena);
  panels.reserve(std::max(kInline, breaks.size()));
  QuadResult<K> out;
  auto make = [&](double a, double b) {
    Panel p{a, b, 0, 0, {}};
    p.value = gauss_kronrod_panel<K, N>(f, a, b, p.error, p.nested);
    out.evaluations += N;
    return p;
  };
  for (size_t i = 0; i + 1 < breaks.size(); ++i)
    if (breaks[i + 1] > breaks[i]) panels.push_back(make(breaks[i], breaks[i + 1]));
  auto steering = [&](const Panel& p) { return nested_steers ? p.error + p.nested : p.error; };
  while (true) {
    double total = 0;
    size_t worst = 0;
    for (size_t i = 0; i < panels.size(); ++i) {
      total += steering(panels[i]);
      if (steering(panels[i]) > steering(panels[worst])) worst = i;
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
    out.error += p.error + p.nested;
  }
  out.panels = int(panels.size());
  return out;
}

}  // namespace dspbr
