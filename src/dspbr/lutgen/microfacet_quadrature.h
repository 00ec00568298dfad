// Deterministic quadrature of the directional albedos behind the energy-compensation tables
// (lutgen/albedo.h, integrator Quad), over the microfacet normal h = (sin t cos p, sin t sin p, cos t)
// for v = (sqrt(1 - mu^2), 0, mu), with l = reflect(v, h) (dl = 4 (v.h) dh) or the refracted
// direction (Walter et al. 2007's Jacobian; its eta factors cancel with the spec's eta_o^2):
//
//   GGX (alpha > 0): the polar variable w in [0, 1] with u = 1 - w^2 the GGX CDF variable,
//     tan^2 t = alpha^2 u / (1 - u), so that D(h) (h.n) dh = 2 w dw dp / (2 pi): the peak is spread
//     over [0, 1] at any roughness and 1 / (h.n) loses its 1 / sqrt(1 - u) (the GGX rows of
//     validate/lut_reference.h integrate in u, with fixed panels: an independent rule);
//       E_m = Integral G2(v, l) (v.h) / (mu h.n) ...,  B = the same times (1 - v.h)^5;
//       E_g (rough dielectric) = Integral (v.h) / (mu h.n) [F_d G2(v, l_r) + (1 - F_d) G2(v, l_t)] ...
//   Sheen: the polar variable cos t in [0, 1] (dh = d(cos t) dp), E_b = Integral f_b(v, l) (l.n) 4 (v.h) dh.
//
// At fixed t, v.h = A cos p + B is monotone in p, and every term switches on or off at a
// threshold on v.h: v.h > 0, the reflection above the horizon (v.h > mu / (2 h.n)), total
// internal reflection (v.h < sqrt(1 - 1/eta^2)) and the refraction below the horizon (closed
// form, below). The azimuth is split where v.h crosses a threshold and each piece integrated with
// the smoothstep substitution (square-root behaviour at its ends, e.g. Fresnel at the TIR edge);
// the polar variable is split where a piece appears or vanishes (a threshold meets v.h at p = 0 or
// p = pi: a kink of the azimuthal integral; a scan, then a root finder). Both levels are adaptive
// Gauss-Kronrod (gauss_kronrod.h); the error stated is the sum of the embedded estimates.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "dspbr/gauss_kronrod.h"

namespace dspbr {

// Largest number of panels per level of the quadrature (bounds the time of a cell whatever the
// tolerance; a cell that stops there states its larger error).
constexpr int kQuadMaxPanels = 200;

// {E_m, B} of GGX at view cosine mu (> 0) and alpha (> 0, isotropic).
QuadResult<2> ggx_moments_quadrature(double mu, double alpha, double tolerance);

// E_g of the rough dielectric interface with eta_i on v's side, eta_o on the other, Schlick
// F_0 = f0, alpha > 0 (lutgen/albedo.h glass_E); at eta_i = eta_o the limit eta -> 1+ of M_t.
QuadResult<1> dielectric_albedo_quadrature(double mu, double alpha, double f0, double eta_i, double eta_o,
                                      double tolerance);

// E_b of the main (ash = false) or alternative sheen at alpha_b (> 0).
QuadResult<1> sheen_albedo_quadrature(double mu, double alpha_b, bool ash, double tolerance);

// 2 Integral_0^1 g(mu) mu dmu of a directional quadrature g(mu, tolerance) -> QuadResult<K>, in
// mu = t^2 (4 t^3 dt: no square-root behaviour of g at grazing), first panels split at the
// cosines `mu_breaks` (kinks of g, any order), the directional values' errors included. Half the
// tolerance goes to g, half to the outer rule's own estimate, which alone steers its bisection
// (gauss_kronrod.h). g's share is spread by weight: g at t is asked for 0.5 tol (5/4) / sqrt(w),
// w = 4 t^3, so its weighted errors add up to at most Integral w 0.5 tol (5/4) w^(-1/2) dt =
// 0.5 tol (looser where the weight is small, i.e. at grazing, where g is the dearest; capped at
// 1e3 tol). The outer rule is QK31: each node costs a directional quadrature, and on the smooth
// pieces between the kinks one 31-node panel usually meets the target where QK15 needs 3 to 5
// (fewer nodes in all).
template <int K, class G>
QuadResult<K> cosine_average_quadrature(G&& g, const std::vector<double>& mu_breaks, double tolerance) {
  std::vector<double> t = {0.0};
  for (double m : mu_breaks)
    if (m > 0 && m < 1) t.push_back(std::sqrt(m));
  t.push_back(1.0);
  std::sort(t.begin(), t.end());
  long inner = 0;
  QuadResult<K> r = integrate_adaptive<K, 31>(
      [&](double x, QuadValues<K>& v, double& e) {
        const double mu = x * x, w = 4.0 * x * x * x;
        const double g_tolerance = w > 0 ? std::min(1e3, 0.625 / std::sqrt(w)) * tolerance : 1e3 * tolerance;
        const QuadResult<K> d = g(mu, g_tolerance);
        inner += d.evaluations;
        for (int k = 0; k < K; ++k) v[size_t(k)] = w * d.value[size_t(k)];
        e = w * d.error;
      },
      t, 0.5 * tolerance, kQuadMaxPanels, /*nested_steers=*/false);
  r.evaluations = inner;
  return r;
}

}  // namespace dspbr
