// LUT-free closed forms for the energy-compensation albedos (spec "Energy Preservation",
// "Multiple-Scattering GGX BRDFs", "Diffuse BRDF", "Sheen BRDF").
//
//   E_m(mu; r)          = 1 - (1 - u)^2 S_Em(r; u, mu),  u = mu / (mu + r^2)   (GGX_E)
//   E_m,avg(r)          = 1 - r^4 P(r), P piecewise polynomial (3 pieces)      (GGX_E_avg)
//   E(mu; r, f0)        = f0 E_m + (1 - f0) E_5 + F_ms(f0, 1; E_m,avg) (1 - E_m)   (Base_E)
//   E_avg(r, f0)        = f0 E_m,avg + (1 - f0) E_5,avg + F_ms(f0, 1; E_m,avg) (1 - E_m,avg)
//   E_b(mu; alpha_b)    = S_b(l; 1 + log10(mu)/3, mu / (mu + sqrt(alpha_b)/2)),  l = -log2(alpha_b)/8  (Sheen_E)
//   E_b,ash(mu; alpha_b) = S_a(l; sqrt(mu), mu / (mu + sqrt(alpha_b)/2))    (Sheen_ash_E, alternative sheen)
//
// Consistent families: P is fitted to the cosine average 2 Integral E_m mu dmu of the *fitted*
// E_m (relative error of 1 - E_m,avg, which M_r,ms divides by), and Q_5,avg to that of the fitted
// E_5, so that the multiple-scattering lobe built from the fits integrates to 1 - E_m (white furnace).
// 1 - (1 - u)^2 S makes the mirror exact (E_m = 1 at r = 0, u = 1) and follows the small-roughness
// limit 1 - E_m ~ alpha^2 / mu^2 (Smith Lambda ~ alpha^2 tan^2 / 4) with S of order one, so the
// fitted 1 - E_m is accurate in relative terms where it is small; 1 - E_m,avg then behaves like
// alpha^2 ln(1/alpha) (r^4 P, P a polynomial in ln r below r = 0.1), which the average fit follows
// to 1e-3 relative and 1e-4 absolute.
//
// Base_E needs no 3D fit: Schlick's F(v.h; f0, 1) = f0 + (1 - f0)(1 - v.h)^5 is affine in f0, so
// Integral M_r F mu_l dl = f0 E_m + (1 - f0) E_5 with E_5(mu; r) = Integral M_r (1 - v.h)^5 mu_l dl,
// and the multiple-scattering part integrates in closed form to F_ms (1 - E_m) (lutgen/albedo.h).
// Only E_5 (2D, E_5 = S_E5(r; mu, u)) and E_5,avg (1D) are fitted in addition to E_m and E_m,avg.
//
// P(x, y) = sum_{i, j = 0..6} a_ij x^i y^j (tensor-product polynomial, 49 coefficients);
// S(x; y1, y2) = P(x, y1) + P'(x, y2), P' without its j = 0 column (42 coefficients): 91 in all,
// linear in them (Ceres converges from any start; Lawson reweighting behaves as for linear minimax).
// Each axis pair (y1, y2) couples a plain cosine variable with a boundary-layer variable.
// Q(x) = sum_k a_k X^k, k = 0..7 (8 parameters); P: 3 pieces of degree 6 (21 parameters).
// (Degree 6 was chosen by measurement: degree 5 misses the whole-domain targets, see docs/fits.md.)
// u = mu / (mu + alpha) stretches the grazing boundary layer of E_m (width ~ alpha = r^2, which a
// polynomial in mu cannot follow) to the whole axis; at r = 0, u = 1 (the mirror: E_m = 1).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>

namespace dspbr::fit {

constexpr int kPoly2Degree = 6;
constexpr int kPoly2Params = (kPoly2Degree + 1) * (kPoly2Degree + 1);
constexpr int kDualParams = kPoly2Params + (kPoly2Degree + 1) * kPoly2Degree;
constexpr int kPoly1Params = 8;
constexpr int kAvgDegree = 6;
constexpr int kAvgParams = 3 * (kAvgDegree + 1);

// The polynomials are written in the shifted variables X = 2x - 1 in [-1, 1] (monomials on [0, 1]
// are ill-conditioned: the fitted coefficients reached 5e3 and float evaluation lost ~1e-3).
// P(x, y), coefficient a_ij at q[i * (degree + 1) + j] of X^i Y^j, Horner in Y inside Horner in X.
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

// S(x; y1, y2) = P(x, y1) + P'(x, y2): q[0..49) is P, q[49 + 6 i + (j - 1)] the a'_ij, j >= 1.
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
// E_m,avg form: 1 - r^4 P_k(Z), piecewise in r with pieces k = 0, 1, 2 on [0, 0.1), [0.1, 0.3),
// [0.3, 1]; P_k = sum_j q[7 k + j] Z^j of degree 6 in Z = 2z - 1, z = ln(r / 0.002) / ln(50) on the
// first piece (the alpha^2 ln(1/alpha) behaviour), linear in r on the others. (One polynomial in
// {R^j, R^j ln r} reached the accuracy only with coefficients ~1e6: useless in float.)
// One minus it (what M_r,ms divides by) is ggx_e_avg_loss.
constexpr double kAvgBreak1 = 0.1, kAvgBreak2 = 0.3, kAvgLogLo = 0.002;
inline int ggx_e_avg_piece(double r) { return r < kAvgBreak1 ? 0 : (r < kAvgBreak2 ? 1 : 2); }
inline double ggx_e_avg_z(double r) {
  switch (ggx_e_avg_piece(r)) {
    case 0: return std::log(r / kAvgLogLo) / std::log(kAvgBreak1 / kAvgLogLo);
    case 1: return (r - kAvgBreak1) / (kAvgBreak2 - kAvgBreak1);
    default: return (r - kAvgBreak2) / (1.0 - kAvgBreak2);
  }
}
template <class T>
T ggx_e_avg_loss(const T* q, double r) {
  if (r <= 0) return T(0.0);
  const T* c = q + (kAvgDegree + 1) * ggx_e_avg_piece(r);
  const double Z = 2.0 * ggx_e_avg_z(r) - 1.0;
  T acc = c[kAvgDegree];
  for (int k = kAvgDegree - 1; k >= 0; --k) acc = acc * T(Z) + c[k];
  return T(r * r * r * r) * acc;
}
template <class T>
T ggx_e_avg_form(const T* q, double r) {
  return T(1.0) - ggx_e_avg_loss<T>(q, r);
}

// u = mu / (mu + r^2); mu = r = 0 is the mirror's grazing limit, taken as u = 1.
inline double ggx_albedo_u(double mu, double r) {
  const double d = mu + r * r;
  return d > 0 ? mu / d : 1.0;
}

// E_m form: 1 - (1 - u)^2 S(r; u, mu); 1 - u = r^2 / (mu + r^2) (0 at mu = r = 0).
template <class T>
T ggx_e_form(const T* q, double mu, double r) {
  const double d = mu + r * r, one_minus_u = d > 0 ? r * r / d : 0.0;
  return T(1.0) - T(one_minus_u * one_minus_u) * dual_poly2<T>(q, r, ggx_albedo_u(mu, r), mu);
}

// Sheen variables: l = -log2(alpha_b)/8 (alpha_b clamped to [2^-8, 1], so l in [0, 1]) and the
// boundary-layer cosine mu / (mu + sqrt(alpha_b)/2) (1 at mu = alpha_b = 0 by convention).
constexpr double kSheenEAlphaMin = 1.0 / 256;
inline double sheen_e_l(double alpha_b) { return -std::log2(std::clamp(alpha_b, kSheenEAlphaMin, 1.0)) / 8.0; }
inline double sheen_e_u(double mu, double alpha_b) {
  const double d = mu + 0.5 * std::sqrt(std::clamp(alpha_b, kSheenEAlphaMin, 1.0));
  return mu / d;
}
// Cosine variable of the main sheen: 1 + log10(mu)/3 on [1e-3, 1] (its albedo grows steeply
// towards grazing with the spec's Lambda fit; mu is clamped to the domain's lower end 1e-3).
constexpr double kSheenEMuMin = 1e-3;
inline double sheen_e_logmu(double mu) { return 1.0 + std::log10(std::clamp(mu, kSheenEMuMin, 1.0)) / 3.0; }

// Parameter sets of the albedo fits (what fits/*.json store and the header embeds).
struct AlbedoFitParams {
  std::array<double, kDualParams> ggx_E{};      // S_Em
  std::array<double, kAvgParams> ggx_E_avg{};   // A, B
  std::array<double, kDualParams> ggx_E5{};     // S_E5
  std::array<double, kPoly1Params> ggx_E5_avg{};
  std::array<double, kDualParams> sheen_E{};    // S_b
  std::array<double, kDualParams> sheen_ash_E{};  // S_b of the alternative sheen
};

// The fitted functions (clamped to [0, 1] where the exact quantity lies in [0, 1]).
double fit_ggx_E(double mu, double r, const AlbedoFitParams& p);
double fit_ggx_E_avg(double r, const AlbedoFitParams& p);
// 1 - E_m(mu; r) and 1 - E_m,avg(r) without the cancellation of 1 - (1 - small) (M_r,ms divides
// by the latter; at r = 0.01 it is ~3e-7, below float resolution of E_m,avg itself).
double fit_ggx_E_loss(double mu, double r, const AlbedoFitParams& p);
double fit_ggx_E_avg_loss(double r, const AlbedoFitParams& p);
double fit_ggx_E5(double mu, double r, const AlbedoFitParams& p);
double fit_ggx_E5_avg(double r, const AlbedoFitParams& p);
double fit_base_E(double mu, double r, double f0, const AlbedoFitParams& p);
double fit_base_E_avg(double r, double f0, const AlbedoFitParams& p);
double fit_sheen_E(double mu, double alpha_b, const AlbedoFitParams& p);
double fit_sheen_ash_E(double mu, double alpha_b, const AlbedoFitParams& p);

}  // namespace dspbr::fit
