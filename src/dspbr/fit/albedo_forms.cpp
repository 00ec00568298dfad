#include "dspbr/fit/albedo_forms.h"

#include <algorithm>

#include "dspbr/fresnel.h"

namespace dspbr::fit {

namespace {
double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }
}  // namespace

double fit_ggx_E(double mu, double r, const AlbedoFitParams& p) {
  return clamp01(dual_poly2<double>(p.ggx_E.data(), r, ggx_albedo_u(mu, r), mu));
}
double fit_ggx_E_avg(double r, const AlbedoFitParams& p) { return clamp01(ggx_e_avg_form<double>(p.ggx_E_avg.data(), r)); }
double fit_ggx_E5(double mu, double r, const AlbedoFitParams& p) {
  return clamp01(dual_poly2<double>(p.ggx_E5.data(), r, mu, ggx_albedo_u(mu, r)));
}
double fit_ggx_E5_avg(double r, const AlbedoFitParams& p) { return clamp01(poly1<double>(p.ggx_E5_avg.data(), r)); }

double fit_base_E(double mu, double r, double f0, const AlbedoFitParams& p) {
  const double em = fit_ggx_E(mu, r, p), e5 = fit_ggx_E5(mu, r, p);
  // F_ms(f0, 1) with E_m,avg (spec eq. multiscatter)
  return f0 * em + (1.0 - f0) * e5 + fresnel_ms(f0, 1.0, fit_ggx_E_avg(r, p)) * (1.0 - em);
}
double fit_base_E_avg(double r, double f0, const AlbedoFitParams& p) {
  const double ea = fit_ggx_E_avg(r, p);
  return f0 * ea + (1.0 - f0) * fit_ggx_E5_avg(r, p) + fresnel_ms(f0, 1.0, ea) * (1.0 - ea);
}
double fit_sheen_E(double mu, double alpha_b, const AlbedoFitParams& p) {
  return clamp01(dual_poly2<double>(p.sheen_E.data(), sheen_e_l(alpha_b), std::sqrt(std::max(0.0, mu)), sheen_e_u(mu, alpha_b)));
}

}  // namespace dspbr::fit
