// Functional forms for the Smith Lambda of the Charlie sheen distribution (spec "Sheen";
// Conty Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF", SIGGRAPH course).
// Every form evaluates ln Lambda as
//   ln Lambda(mu) = L(mu)                   for mu < 0.5
//                 = 2 L(0.5) - L(1 - mu)     otherwise,           L(x) = a0/(1 + a1 x^a2) + a3 x + a4,
// and differs only in how the row p = (a0..a4) depends on alpha_b. Templated on the scalar so
// Ceres can differentiate them (T = ceres::Jet) and the header generator can mirror them.
#pragma once
#include <array>
#include <cmath>

#include "dspbr/sheen.h"

namespace dspbr::fit {

// L(x) = a0/(1 + a1 x^a2) + a3 x + a4; x > 0 (x = 0 would give 0^a2, avoided by the callers' domain).
template <class T>
T sheen_l_row(const T* a, double x) {
  using std::pow;
  return a[0] / (T(1.0) + a[1] * pow(T(x), a[2])) + a[3] * T(x) + a[4];
}

// ln Lambda from a row function row(x) = L(x) (the mirrored construction above).
template <class T, class Row>
T sheen_ln_lambda_mirrored(double mu, Row&& row) {
  if (mu < 0.5) return row(mu);
  return T(2.0) * row(0.5) - row(1.0 - mu);
}

// The spec's form (14 parameters: p0[5], p1[5], c[4]) in the reading of docs/sheen_lambda.md:
// w = c0/(1 + c1 alpha^c2) + c3, p = (1 - w) p0 + w p1.
constexpr int kSheenSpecFormParams = 14;
template <class T>
T sheen_ln_lambda_spec_form(const T* q, double mu, double alpha_b) {
  using std::pow;
  const T w = q[10] / (T(1.0) + q[11] * pow(T(alpha_b), q[12])) + q[13];
  T p[5];
  for (int i = 0; i < 5; ++i) p[i] = (T(1.0) - w) * q[i] + w * q[5 + i];
  return sheen_ln_lambda_mirrored<T>(mu, [&](double x) { return sheen_l_row<T>(p, x); });
}
std::array<double, kSheenSpecFormParams> to_params(const SheenLambdaFit& f);
SheenLambdaFit from_params(const std::array<double, kSheenSpecFormParams>& q);

// The 2017 original (Conty Estevez & Kulla 2017, Table 1; the same numbers are in the
// DSPBR path tracer dspbr-pt, packages/lib/shader/bsdfs/sheen.glsl): rows at alpha_b = 0 and 1,
// p = t p(0) + (1 - t) p(1) with t = (1 - alpha_b)^2 (their "r" is our alpha_b: D ~ sin^(1/r)).
double sheen_lambda_ck17(double cos_theta, double alpha_b);

// Our richer form (docs/fits.md). A GGX-like Smith shape in t^2 = tan^2(theta) = (1 - mu^2)/mu^2,
// corrected by an exponential in mu:
//   Lambda = b (sqrt(1 + A^2 t^2) - 1) exp(c mu / (1 + d mu)),
// with each of b, A, c, d a rational function of s = sqrt(alpha_b):
//   f(s) = (u0 + u1 s + u2 s^2) / (1 + u3 s)            (16 parameters).
// It has the exact limits Lambda -> 0 like t^2 at normal incidence and Lambda ~ 1/mu at grazing.
// Per evaluation: 1 sqrt (alpha_b), 1 sqrt + 1 exp (mu), 6 divisions, ~30 mul/add; the spec's
// form costs 3 pow + 1 exp + 2 divisions + ~30 mul/add.
constexpr int kSheenRichFormParams = 16;
template <class T>
T sheen_rich_coef(const T* u, double s) {
  return (u[0] + u[1] * T(s) + u[2] * T(s * s)) / (T(1.0) + u[3] * T(s));
}
// ln Lambda of the rich form; mu in (0, 1] (mu = 1 gives -inf, i.e. Lambda = 0).
template <class T>
T sheen_ln_lambda_rich_form(const T* q, double mu, double alpha_b) {
  using std::log;
  using std::sqrt;
  const double s = std::sqrt(alpha_b);
  const T b = sheen_rich_coef<T>(q, s), A = sheen_rich_coef<T>(q + 4, s);
  const T c = sheen_rich_coef<T>(q + 8, s), d = sheen_rich_coef<T>(q + 12, s);
  const T x = A * A * T((1.0 - mu * mu) / (mu * mu));
  // sqrt(1 + x) - 1 = x / (sqrt(1 + x) + 1), without cancellation at small x.
  return log(b * x / (sqrt(T(1.0) + x) + T(1.0))) + c * T(mu) / (T(1.0) + d * T(mu));
}
// Lambda of the rich form for any cos_theta (|cos| used; cos = 0 gives +inf, 1 gives 0; |cos| is
// clamped to >= 1e-6 otherwise, as in the generated header).
double sheen_lambda_rich(double cos_theta, double alpha_b, const double* q);

}  // namespace dspbr::fit
