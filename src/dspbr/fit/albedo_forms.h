// LUT-free closed forms for the energy-compensation albedos (issue "Ceres refits", part 2).
//
//   E_m(mu; r)          = S_Em(r; u, mu),  u = mu / (mu + r^2)               (GGX_E)
//   E_m,avg(r)          = 1 - r^3 Q_avg(r)                                  (GGX_E_avg)
//   E(mu; r, f0)        = f0 E_m + (1 - f0) E_5 + F_ms(f0, 1; E_m,avg) (1 - E_m)   (Base_E)
//   E_avg(r, f0)        = f0 E_m,avg + (1 - f0) E_5,avg + F_ms(f0, 1; E_m,avg) (1 - E_m,avg)
//   E_b(mu; alpha_b)    = S_b(l; sqrt(mu), mu / (mu + sqrt(alpha_b)/2)),  l = -log2(alpha_b)/8  (Sheen_E)
//
// Base_E needs no 3D fit: Schlick's F(v.h; f0, 1) = f0 + (1 - f0)(1 - v.h)^5 is affine in f0, so
// Integral M_r F mu_l dl = f0 E_m + (1 - f0) E_5 with E_5(mu; r) = Integral M_r (1 - v.h)^5 mu_l dl,
// and the multiple-scattering part integrates in closed form to F_ms (1 - E_m) (lut/albedo.h).
// Only E_5 (2D, E_5 = S_E5(r; mu, u)) and E_5,avg (1D) are fitted in addition to E_m and E_m,avg.
//
// P(x, y) = sum_{i, j = 0..5} a_ij x^i y^j (tensor-product polynomial, 36 coefficients);
// S(x; y1, y2) = P(x, y1) + P'(x, y2), P' without its j = 0 column (30 coefficients): 66 in all,
// linear in them (Ceres converges from any start; Lawson reweighting behaves as for linear minimax).
// Each axis pair (y1, y2) couples a plain cosine variable with a boundary-layer variable.
// Q(x) = (a0 + a1 x + a2 x^2 + a3 x^3) / (1 + b1 x + b2 x^2 + b3 x^3)   (7 parameters).
// u = mu / (mu + alpha) stretches the grazing boundary layer of E_m (width ~ alpha = r^2, which a
// polynomial in mu cannot follow) to the whole axis; at r = 0, u = 1 (the mirror: E_m = 1).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>

namespace dspbr::fit {

constexpr int kPoly2Degree = 5;
constexpr int kPoly2Params = (kPoly2Degree + 1) * (kPoly2Degree + 1);
constexpr int kDualParams = kPoly2Params + (kPoly2Degree + 1) * kPoly2Degree;
constexpr int kPoly1Params = 8;

// The polynomials are written in the shifted variables X = 2x - 1 in [-1, 1] (monomials on [0, 1]
// are ill-conditioned: the fitted coefficients reached 5e3 and float evaluation lost ~1e-3).
// P(x, y), coefficient a_ij at q[i * 6 + j] of X^i Y^j, Horner in Y inside Horner in X.
template <class T>
T poly2(const T* q, double x, double y) {
  const double X = 2.0 * x - 1.0, Y = 2.0 * y - 1.0;
  T acc = T(0.0);
  for (int i = kPoly2Degree; i >= 0; --i) {
    T row = q[i * (kPoly2Degree + 1) + kPoly2Degree];
    for (int j = kPoly2Degree - 1; j >= 0; --j) row = row * T(Y) + q[i * (kPoly2Degree + 1) + j];
    acc = acc * T(X) + row;
  }
  return acc;
}

// S(x; y1, y2) = P(x, y1) + P'(x, y2): q[0..36) is P, q[36 + 5 i + (j - 1)] the a'_ij, j >= 1.
template <class T>
T dual_poly2(const T* q, double x, double y1, double y2) {
  const double X = 2.0 * x - 1.0, Y1 = 2.0 * y1 - 1.0, Y2 = 2.0 * y2 - 1.0;
  T acc = T(0.0);
  for (int i = kPoly2Degree; i >= 0; --i) {
    const T* b = q + kPoly2Params + i * kPoly2Degree;  // a'_i1 .. a'_i5
    T row2 = b[kPoly2Degree - 1];
    for (int j = kPoly2Degree - 2; j >= 0; --j) row2 = row2 * T(Y2) + b[j];
    row2 = row2 * T(Y2);  // no j = 0 term
    T row1 = q[i * (kPoly2Degree + 1) + kPoly2Degree];
    for (int j = kPoly2Degree - 1; j >= 0; --j) row1 = row1 * T(Y1) + q[i * (kPoly2Degree + 1) + j];
    acc = acc * T(X) + (row1 + row2);
  }
  return acc;
}

// Q(x) = sum_k a_k X^k, X = 2x - 1.
template <class T>
T poly1(const T* q, double x) {
  const double X = 2.0 * x - 1.0;
  T acc = q[kPoly1Params - 1];
  for (int k = kPoly1Params - 2; k >= 0; --k) acc = acc * T(X) + q[k];
  return acc;
}
// E_m,avg form: 1 - r^3 Q(r).
template <class T>
T ggx_e_avg_form(const T* q, double r) {
  return T(1.0) - T(r * r * r) * poly1<T>(q, r);
}

// u = mu / (mu + r^2); mu = r = 0 is the mirror's grazing limit, taken as u = 1.
inline double ggx_albedo_u(double mu, double r) {
  const double d = mu + r * r;
  return d > 0 ? mu / d : 1.0;
}

// Sheen variables: l = -log2(alpha_b)/8 (alpha_b clamped to [2^-8, 1], so l in [0, 1]) and the
// boundary-layer cosine mu / (mu + sqrt(alpha_b)/2) (1 at mu = alpha_b = 0 by convention).
constexpr double kSheenEAlphaMin = 1.0 / 256;
inline double sheen_e_l(double alpha_b) { return -std::log2(std::clamp(alpha_b, kSheenEAlphaMin, 1.0)) / 8.0; }
inline double sheen_e_u(double mu, double alpha_b) {
  const double d = mu + 0.5 * std::sqrt(std::clamp(alpha_b, kSheenEAlphaMin, 1.0));
  return mu / d;
}

// Parameter sets of the albedo fits (what fits/*.json store and the header embeds).
struct AlbedoFitParams {
  std::array<double, kDualParams> ggx_E{};      // S_Em
  std::array<double, kPoly1Params> ggx_E_avg{}; // Q_avg
  std::array<double, kDualParams> ggx_E5{};     // S_E5
  std::array<double, kPoly1Params> ggx_E5_avg{};
  std::array<double, kDualParams> sheen_E{};    // S_b
};

// The fitted functions (clamped to [0, 1] where the exact quantity lies in [0, 1]).
double fit_ggx_E(double mu, double r, const AlbedoFitParams& p);
double fit_ggx_E_avg(double r, const AlbedoFitParams& p);
double fit_ggx_E5(double mu, double r, const AlbedoFitParams& p);
double fit_ggx_E5_avg(double r, const AlbedoFitParams& p);
double fit_base_E(double mu, double r, double f0, const AlbedoFitParams& p);
double fit_base_E_avg(double r, double f0, const AlbedoFitParams& p);
double fit_sheen_E(double mu, double alpha_b, const AlbedoFitParams& p);

}  // namespace dspbr::fit
