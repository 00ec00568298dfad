#include "dspbr/fit/albedo_forms.h"

#include <algorithm>

#include "dspbr/fresnel.h"

namespace dspbr::fit {

namespace {
double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }
}  // namespace

double fit_ggx_E(double mu, double r, const AlbedoFitParams& p) {
  return 1.0 - fit_ggx_E_loss(mu, r, p);
}
double fit_ggx_E_loss(double mu, double r, const AlbedoFitParams& p) {
  const double d = mu + r * r, w = d > 0 ? r * r / d : 0.0;
  return clamp01(w * w * dual_poly2<double>(p.ggx_E.data(), r, ggx_albedo_u(mu, r), mu));
}
double fit_ggx_E_avg_loss(double r, const AlbedoFitParams& p) { return clamp01(ggx_e_avg_loss<double>(p.ggx_E_avg.data(), r)); }
double fit_ggx_E_avg(double r, const AlbedoFitParams& p) { return clamp01(ggx_e_avg_form<double>(p.ggx_E_avg.data(), r)); }
double fit_ggx_E5(double mu, double r, const AlbedoFitParams& p) {
  return clamp01(dual_poly2<double>(p.ggx_E5.data(), r, mu, ggx_albedo_u(mu, r)));
}
double fit_ggx_E5_avg(double r, const AlbedoFitParams& p) { return clamp01(poly1<double>(p.ggx_E5_avg.data(), r)); }

double fit_base_E(double mu, double r, double f0, const AlbedoFitParams& p) {
  const double loss = fit_ggx_E_loss(mu, r, p), e5 = fit_ggx_E5(mu, r, p);
  // F_ms(f0, 1) with E_m,avg (spec eq. multiscatter)
  return f0 * (1.0 - loss) + (1.0 - f0) * e5 + fresnel_ms(f0, 1.0, fit_ggx_E_avg(r, p)) * loss;
}
double fit_base_E_avg(double r, double f0, const AlbedoFitParams& p) {
  const double loss = fit_ggx_E_avg_loss(r, p), ea = 1.0 - loss;
  return f0 * ea + (1.0 - f0) * fit_ggx_E5_avg(r, p) + fresnel_ms(f0, 1.0, ea) * loss;
}
namespace {
double sheen_form(const std::array<double, kDualParams>& q, double mu, double alpha_b) {
  return dual_poly2<double>(q.data(), sheen_e_l(alpha_b), std::sqrt(std::max(0.0, mu)), sheen_e_u(mu, alpha_b));
}
}  // namespace
// (the sheen albedos are not clamped to 1: the main sheen's exceeds 1 at grazing, the
// alternative's reaches ~6; both are clamped at 0)
double fit_sheen_E(double mu, double alpha_b, const AlbedoFitParams& p) {
  return std::max(0.0, dual_poly2<double>(p.sheen_E.data(), sheen_e_l(alpha_b), sheen_e_logmu(mu), sheen_e_u(mu, alpha_b)));
}
double fit_sheen_ash_E(double mu, double alpha_b, const AlbedoFitParams& p) { return std::max(0.0, sheen_form(p.sheen_ash_E, mu, alpha_b)); }

}  // namespace dspbr::fit
