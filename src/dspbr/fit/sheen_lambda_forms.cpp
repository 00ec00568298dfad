#include "dspbr/fit/sheen_lambda_forms.h"

#include <algorithm>

namespace dspbr::fit {

std::array<double, kSheenSpecFormParams> to_params(const SheenLambdaFit& f) {
  std::array<double, kSheenSpecFormParams> q{};
  for (int i = 0; i < 5; ++i) {
    q[size_t(i)] = f.p0[size_t(i)];
    q[size_t(5 + i)] = f.p1[size_t(i)];
  }
  for (int i = 0; i < 4; ++i) q[size_t(10 + i)] = f.c[size_t(i)];
  return q;
}

SheenLambdaFit from_params(const std::array<double, kSheenSpecFormParams>& q) {
  SheenLambdaFit f{};
  for (int i = 0; i < 5; ++i) {
    f.p0[size_t(i)] = q[size_t(i)];
    f.p1[size_t(i)] = q[size_t(5 + i)];
  }
  for (int i = 0; i < 4; ++i) f.c[size_t(i)] = q[size_t(10 + i)];
  return f;
}

double sheen_lambda_ck17(double cos_theta, double alpha_b) {
  // Conty Estevez & Kulla 2017, Table 1: rows for r = 0 and r = 1, interpolated with (1 - r)^2.
  static const double p_at0[5] = {25.3245, 3.32435, 0.16801, -1.27393, -4.85967};
  static const double p_at1[5] = {21.5473, 3.82987, 0.19823, -1.97760, -4.32054};
  const double t = (1.0 - alpha_b) * (1.0 - alpha_b);
  double p[5];
  for (int i = 0; i < 5; ++i) p[i] = t * p_at0[i] + (1.0 - t) * p_at1[i];
  const double mu = std::min(1.0, std::abs(cos_theta));
  return std::exp(sheen_ln_lambda_mirrored<double>(mu, [&](double x) { return sheen_l_row<double>(p, x); }));
}

}  // namespace dspbr::fit

namespace dspbr::fit {

double sheen_lambda_rich(double cos_theta, double alpha_b, const double* q) {
  const double mu = std::min(1.0, std::abs(cos_theta));
  if (mu == 0.0) return HUGE_VAL;  // grazing: fully masked
  if (mu == 1.0) return 0.0;       // normal incidence: no masking (t = 0)
  // Same clamp as the generated header: below cos 1e-6, Lambda > 1e5 and G changes by < 1e-5.
  return std::exp(sheen_ln_lambda_rich_form<double>(q, std::max(mu, 1e-6), alpha_b));
}

}  // namespace dspbr::fit
