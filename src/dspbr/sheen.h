// Sheen microfacet model: Charlie distribution and its shadowing (spec "Sheen"; Conty Estevez &
// Kulla 2017), plus the alternative visibility term (spec "Sheen", [NP13]).
// cos arguments are cosines to the normal; alpha_b = r_b^2.
#pragma once
#include <array>

#include "dspbr/vec3.h"

namespace dspbr {

// The two sheen models: Charlie D_b with the spec's Lambda fit (Main) or the alternative
// visibility of [NP13] (Ash).
enum class SheenModel { Main, Ash };
// Smallest alpha_b the BSDF and the tables use; smaller values are clamped up to it (D_b is
// undefined at 0): 1/256, sheen roughness 1/16, where the renderer layout's sheen tables start, so
// that the lobe and the E_b of its layering agree (with 1e-3 the lobe narrowed below 1/256 while
// the tables did not, and a white furnace lost up to 14 %: the fourth fresh tester's pass).
constexpr double kMinAlphaB = 1.0 / 256.0;

// Charlie distribution D_b(h) = (2 + 1/alpha_b) sin^(1/alpha_b)(theta_h) / (2 pi), zero below
// the surface. Requires alpha_b > 0.
double charlie_d(double cos_theta_h, double alpha_b);

// Coefficients of the functional form of the spec's Lambda fit:
//   L(x) = a0 / (1 + a1 x^a2) + a3 x + a4 at two anchor rows p0, p1, blended with
//   w(alpha_b) = c0 / (1 + c1 alpha_b^c2) + c3 as  p(alpha_b) = (1 - w) p0 + w p1.
// (The spec's table caption says (1 - w) p1 + w p0; the exact Lambda supports the reading above,
// see docs/sheen_lambda.md and tests/test_sheen.cpp.)
struct SheenLambdaFit {
  std::array<double, 5> p0, p1;
  std::array<double, 4> c;
  bool ck17_blend = false;  // w = 1 - (1 - alpha_b)^2 instead (Conty Estevez & Kulla 2017; c unused)
};

// The coefficients printed in the DSPBR 2025x spec (Table sheen-lambda-fit and -w).
const SheenLambdaFit& sheen_lambda_fit_spec();
// The older fit of Conty Estevez & Kulla 2017 (their two rows for alpha = 0 and 1, blended by
// 1 - (1 - alpha_b)^2): what implementations written before DSPBR 2025x use; the conformance
// diagnosis's Deviation::OldSheenLambda.
const SheenLambdaFit& sheen_lambda_fit_ck17();

// The fit at one alpha_b: the blended row p(alpha_b) and L(0.5) computed once, for the many
// directions evaluated at a fixed roughness (a quadrature cell: 5 powers per sheen BRDF
// evaluation become 2, measured 2026-12-04).
class SheenLambda {
 public:
  SheenLambda(double alpha_b, const SheenLambdaFit& fit);
  // L(x; alpha_b) of the fit form.
  double L(double x) const;
  // Lambda(cos; alpha_b) = exp(L(|cos|)) for |cos| < 0.5, exp(2 L(0.5) - L(1 - |cos|)) otherwise.
  double operator()(double cos_theta) const;

 private:
  std::array<double, 5> p_;
  double l_half_;
};

inline double sheen_lambda(double cos_theta, double alpha_b, const SheenLambdaFit& fit) {
  return SheenLambda(alpha_b, fit)(cos_theta);
}
inline double sheen_lambda(double cos_theta, double alpha_b) {
  return sheen_lambda(cos_theta, alpha_b, sheen_lambda_fit_spec());
}

// The exact Smith Lambda of the Charlie distribution, by numerical integration:
//   Lambda(w) = (1 / cos_theta) Integral max(0, w.h) D_b(h) dh - 1,
// with the azimuth integral done in closed form and composite Gauss-Legendre in theta_h,
// split at the kink theta_h = pi/2 - theta. Relative accuracy better than 1e-7 for
// alpha_b in [1e-3, 1], cos_theta in [1e-5, 0.9999] (checked against a uniform 8000-panel rule
// in theta_h in tests/test_fit_sheen.cpp); near cos_theta = 1, Lambda -> 0 and the final
// "total / cos - 1" limits the absolute accuracy to ~1e-14.
double sheen_lambda_exact(double cos_theta, double alpha_b);

// Sheen shadowing-masking G_b = chi+(v.h) chi+(l.h) / (1 + Lambda(v.n) + Lambda(l.n)), from the
// two Lambdas, or with them from the fit.
double sheen_g2(const Vec3& v, const Vec3& l, const Vec3& h, double lambda_v, double lambda_l);
double sheen_g2(const Vec3& v, const Vec3& l, const Vec3& h, double alpha_b, const SheenLambdaFit& fit);

// Main sheen BRDF M_b = D_b G_b / (4 |v.n| |l.n|) (spec "Sheen"), without the sheen colour.
double sheen_brdf(const Vec3& v, const Vec3& l, double alpha_b, const SheenLambdaFit& fit);
inline double sheen_brdf(const Vec3& v, const Vec3& l, double alpha_b) {
  return sheen_brdf(v, l, alpha_b, sheen_lambda_fit_spec());
}
// The same with the fit at alpha_b and lambda_v = lambda(v.n) given (a fixed view and roughness).
double sheen_brdf(const Vec3& v, const Vec3& l, double alpha_b, const SheenLambda& lambda, double lambda_v);

// Alternative sheen BRDF with the Neubelt-Pettineo visibility (spec "Sheen", [NP13]):
// M_b = D_b / (4 (v.n + l.n - (v.n)(l.n))).
double sheen_brdf_ash(const Vec3& v, const Vec3& l, double alpha_b);

}  // namespace dspbr
