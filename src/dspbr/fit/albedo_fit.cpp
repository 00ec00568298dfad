#include "dspbr/fit/albedo_fit.h"

#include <algorithm>

#include "dspbr/fresnel.h"
#include "dspbr/quadrature.h"
#include "dspbr/validate/lut_reference.h"

namespace dspbr::fit {

namespace {

struct EmResidual {  // E_m form - target
  double mu, r, target;
  template <class T>
  bool operator()(const T* q, T* res) const {
    res[0] = ggx_e_form<T>(q, mu, r) - T(target);
    return true;
  }
};
// Error of 1 - E_m,avg (the divisor of M_r,ms) in units of its tolerance: 1e-3 relative (the
// furnace) or 1e-4 absolute (consistency of E_m,avg itself), whichever is stricter.
struct EavgRelResidual {
  double r, target;  // target = 1 - 2 Integral E^ mu dmu
  template <class T>
  bool operator()(const T* q, T* res) const {
    res[0] = (ggx_e_avg_loss<T>(q, r) - T(target)) / T(std::min(1e-3 * target, 1e-4));
    return true;
  }
};
struct DualResidual {  // S(x; y1, y2) - target
  double x, y1, y2, target;
  template <class T>
  bool operator()(const T* q, T* res) const {
    res[0] = dual_poly2<T>(q, x, y1, y2) - T(target);
    return true;
  }
};
struct P1Residual {
  double x, target;
  template <class T>
  bool operator()(const T* q, T* res) const {
    res[0] = poly1<T>(q, x) - T(target);
    return true;
  }
};

// Cell-centred roughnesses on [0, 1] with the given offset.
std::vector<double> r_grid(int n, double offset) {
  std::vector<double> g;
  for (int i = 0; i < n; ++i) g.push_back((i + offset) / n);
  return g;
}
// n roughnesses geometric on [lo, hi) at the given offset within each step.
std::vector<double> small_r_grid(double lo, double hi, int n, double offset) {
  std::vector<double> g;
  for (int i = 0; i < n; ++i) g.push_back(lo * std::pow(hi / lo, (i + offset) / n));
  return g;
}

std::vector<double> sorted_unique(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

validate::RefQuadrature quadrature(const AlbedoFitSettings& s) { return validate::RefQuadrature{s.panels}; }

// Reference albedos at one (mu, r): E_m and E_5 = Integral M_r (1 - v.h)^5 mu_l dl.
struct GgxRef {
  double e_m = 0, e_5 = 0, error = 0;
};
GgxRef ggx_ref(double mu, double r, const validate::RefQuadrature& q) {
  const auto em = validate::ggx_albedo_ref(mu, r, q), e5 = validate::ggx_fresnel_albedo_ref(mu, r, 0.0, q);
  return {em.value, e5.value, std::max(em.error, e5.error)};
}

}  // namespace

double fitted_ggx_E_cosine_average(double r, const AlbedoFitParams& p) {
  return cosine_average([&](double mu) { return fit_ggx_E(mu, r, p); });
}
double fitted_ggx_E5_cosine_average(double r, const AlbedoFitParams& p) {
  return cosine_average([&](double mu) { return fit_ggx_E5(mu, r, p); });
}

AlbedoFitParams albedo_fit_start() {
  AlbedoFitParams p;
  p.ggx_E[0] = 0.5;
  for (int k = 0; k < 3; ++k) p.ggx_E_avg[size_t(k * (kAvgDegree + 1))] = 1.0;
  p.ggx_E5[0] = 0.1;
  p.ggx_E5_avg[0] = 0.1;
  p.sheen_E[0] = 0.5;
  p.sheen_ash_E[0] = 0.5;
  return p;
}

AlbedoFitResult fit_albedos(const AlbedoFitSettings& s, const FitContext& ctx) {
  const auto q = quadrature(s);
  // Roughness: the mirror r = 0, geometric steps below 0.1 (the boundary layer u is thinnest
  // there), cell-centred above, and r = 1. Cosines: a little beyond the judged domain (mu_min / 2)
  // so that its edge is interpolated, not extrapolated.
  auto rs = r_grid(s.n_r, 0.5);
  for (double r : small_r_grid(0.004, 0.1, ctx.quick ? 3 : 8, 0.0)) rs.push_back(r);
  rs.push_back(0.0);
  rs.push_back(1.0);
  rs = sorted_unique(rs);
  auto mus = cosine_grid(0.5 * s.mu_min, 1.0, s.n_mu, 0.5);
  mus.push_back(0.5 * s.mu_min);
  mus.push_back(1.0);
  mus = sorted_unique(mus);
  const size_t nm = mus.size();
  const auto ref = parallel_map<GgxRef>(ctx, rs.size() * nm, [&](size_t i) { return ggx_ref(mus[i % nm], rs[i / nm], q); });
  auto alphas = geometric_grid(s.alpha_b_min, 1.0, s.n_r);
  // Sheen: cosines from mu_min exactly (the main sheen's albedo grows without bound below it).
  auto mus_b = cosine_grid(s.mu_min, 1.0, s.n_mu, 0.5);
  mus_b.push_back(s.mu_min);
  mus_b.push_back(1.0);
  mus_b = sorted_unique(mus_b);
  const size_t nb = mus_b.size();
  struct SheenRef {
    double main = 0, ash = 0, error = 0;
  };
  const auto sheen = parallel_map<SheenRef>(ctx, alphas.size() * nb, [&](size_t i) {
    const double mu = mus_b[i % nb], a = alphas[i / nb];
    const auto m = validate::sheen_albedo_ref(mu, a, false, q), x = validate::sheen_albedo_ref(mu, a, true, q);
    return SheenRef{m.value, x.value, std::max(m.error, x.error)};
  });
  AlbedoFitResult out;
  out.params = albedo_fit_start();
  std::vector<EmResidual> em;
  std::vector<DualResidual> e5, sb, sa;
  for (size_t ir = 0; ir < rs.size(); ++ir)
    for (size_t j = 0; j < nm; ++j) {
      const GgxRef& g = ref[ir * nm + j];
      em.push_back({mus[j], rs[ir], g.e_m});
      e5.push_back({rs[ir], mus[j], ggx_albedo_u(mus[j], rs[ir]), g.e_5});
      out.reference_error_max = std::max(out.reference_error_max, g.error);
    }
  for (size_t ia = 0; ia < alphas.size(); ++ia)
    for (size_t j = 0; j < nb; ++j) {
      const SheenRef& r = sheen[ia * nb + j];
      const double l = sheen_e_l(alphas[ia]), y2 = sheen_e_u(mus_b[j], alphas[ia]);
      sb.push_back({l, sheen_e_logmu(mus_b[j]), y2, r.main});
      sa.push_back({l, std::sqrt(mus_b[j]), y2, r.ash});
      out.reference_error_max = std::max(out.reference_error_max, r.error);
    }
  // ridge: keeps the coefficients ~1e1 instead of ~1e4 (float header) at ~5 % more max error
  MinimaxOptions ridge = s.minimax;
  ridge.ridge = 1e-8;
  out.ggx_E = fit_minimax<kDualParams>(em, out.params.ggx_E, ridge);
  out.ggx_E5 = fit_minimax<kDualParams>(e5, out.params.ggx_E5, ridge);
  out.sheen_E = fit_minimax<kDualParams>(sb, out.params.sheen_E, ridge);
  out.sheen_ash_E = fit_minimax<kDualParams>(sa, out.params.sheen_ash_E, ridge);
  // Consistent averages: fitted to the cosine averages of the fitted E_m and E_5 on a fine
  // roughness grid (these are cheap: no reference quadrature).
  auto ra = r_grid(ctx.quick ? 16 : 64, 0.5);
  for (double r : small_r_grid(kAvgLogLo, kAvgBreak1, ctx.quick ? 8 : 32, 0.5)) ra.push_back(r);
  for (double r : {kAvgLogLo, kAvgBreak1, kAvgBreak2, 1.0}) ra.push_back(r);
  ra = sorted_unique(ra);
  std::vector<EavgRelResidual> ea;
  std::vector<P1Residual> e5a;
  for (double r : ra) {
    // 1 - I from the integral of the loss 1 - E^ (no cancellation at small r)
    ea.push_back({r, cosine_average([&](double mu) { return fit_ggx_E_loss(mu, r, out.params); })});
    e5a.push_back({r, fitted_ggx_E5_cosine_average(r, out.params)});
  }
  e5a.push_back({0.0, fitted_ggx_E5_cosine_average(0.0, out.params)});
  MinimaxOptions avg_opt = s.minimax;
  avg_opt.lawson_rounds = 10;  // 1D: minimax (the furnace needs the maximum small)
  out.ggx_E_avg = fit_minimax<kAvgParams>(ea, out.params.ggx_E_avg, avg_opt);
  out.ggx_E5_avg = fit_minimax<kPoly1Params>(e5a, out.params.ggx_E5_avg, avg_opt);
  return out;
}

nlohmann::json albedo_report(const AlbedoFitSettings& s, const AlbedoFitParams& p, const FitContext& ctx) {
  const auto q = quadrature(s);
  // Fresh whole-domain grids: offsets and sizes differ from the fit grids; the domain's edges
  // (r = 0, r = 1, mu = mu_min, mu = 1, alpha_b = 1/256 and 1) included.
  const int nr = ctx.quick ? 7 : 29, nm = ctx.quick ? 9 : 37;
  auto rs = r_grid(nr, 0.27);
  for (double r : small_r_grid(0.01, 0.1, ctx.quick ? 2 : 6, 0.37)) rs.push_back(r);
  rs.push_back(0.0);
  rs.push_back(0.01);
  rs.push_back(1.0);
  rs = sorted_unique(rs);
  auto mus = cosine_grid(s.mu_min, 1.0, nm, 0.27);
  mus.push_back(s.mu_min);
  mus.push_back(1.0);
  mus = sorted_unique(mus);
  const size_t nmu = mus.size();
  const std::vector<double> f0s = ctx.quick ? std::vector<double>{0.0, 0.5, 1.0}
                                            : std::vector<double>{0.0, 0.02, 0.04, 0.1, 0.25, 0.5, 0.75, 1.0};
  struct AvgRow {
    double e_avg = 0, e5_avg = 0;
  };
  const auto avg = parallel_map<AvgRow>(ctx, rs.size(), [&](size_t i) {
    const double ea = validate::ggx_albedo_avg_ref(rs[i], q).value;
    // base E_avg(r, 0) = E_5,avg + F_ms(0, 1) (1 - E_m,avg)
    const double b0 = validate::base_albedo_avg_ref(rs[i], 0.0, q).value;
    return AvgRow{ea, b0 - fresnel_ms(0.0, 1.0, ea) * (1.0 - ea)};
  });
  const auto cells = parallel_map<GgxRef>(ctx, rs.size() * nmu, [&](size_t i) { return ggx_ref(mus[i % nmu], rs[i / nmu], q); });
  std::vector<double> alphas = geometric_grid(s.alpha_b_min, 1.0, nr);
  for (double& a : alphas) a = std::min(1.0, a * std::pow(1.0 / s.alpha_b_min, 0.37 / (nr - 1)));
  alphas.push_back(s.alpha_b_min);
  alphas = sorted_unique(alphas);
  struct SheenCell {
    double main = 0, ash = 0;
  };
  const auto sheen = parallel_map<SheenCell>(ctx, alphas.size() * nmu, [&](size_t i) {
    const double mu = mus[i % nmu], a = alphas[i / nmu];
    return SheenCell{validate::sheen_albedo_ref(mu, a, false, q).value, validate::sheen_albedo_ref(mu, a, true, q).value};
  });
  ErrorStats em, ea, be, ba, sb, sa, cons_avg, cons_loss, cons_5avg, furnace_metal, furnace_diel;
  std::vector<double> map_em, map_sb;  // signed errors on the fresh grid (plots)
  const std::vector<double> bands = {0.0, 0.05, 0.25, 0.5, 1.0 + 1e-9};
  std::vector<ErrorStats> metal_band(bands.size() - 1);
  for (size_t ir = 0; ir < rs.size(); ++ir) {
    const double r = rs[ir];
    const double ea_fit = fit_ggx_E_avg(r, p), ea_int = fitted_ggx_E_cosine_average(r, p);
    ea.add(ea_fit - avg[ir].e_avg);
    cons_avg.add(ea_fit - ea_int);
    cons_5avg.add(fit_ggx_E5_avg(r, p) - fitted_ggx_E5_cosine_average(r, p));
    // White opaque dielectric per f0: its B_c uses the fitted Base_E, its average and the cosine
    // average of the fitted Base_E (what the lobe integrates to).
    std::vector<double> base_int(f0s.size());
    for (size_t k = 0; k < f0s.size(); ++k) {
      const double exact = f0s[k] * avg[ir].e_avg + (1 - f0s[k]) * avg[ir].e5_avg +
                           fresnel_ms(f0s[k], 1.0, avg[ir].e_avg) * (1 - avg[ir].e_avg);
      ba.add(fit_base_E_avg(r, f0s[k], p) - exact);
      base_int[k] = cosine_average([&](double m) { return fit_base_E(m, r, f0s[k], p); });
    }
    // M_r,ms built from the fits integrates to (1 - E^(mu)) (1 - 2 Int E^ mu dmu) / (1 - E^_avg).
    const double loss_int = cosine_average([&](double m) { return fit_ggx_E_loss(m, r, p); });
    const double loss_fit = fit_ggx_E_avg_loss(r, p);
    const double ms_ratio = loss_fit > 0 ? loss_int / loss_fit : 0.0;
    if (loss_int > 0) cons_loss.add(loss_fit / loss_int - 1.0);
    for (size_t j = 0; j < nmu; ++j) {
      const double mu = mus[j];
      const GgxRef& c = cells[ir * nmu + j];
      const double e_hat = fit_ggx_E(mu, r, p);
      em.add(e_hat - c.e_m);
      map_em.push_back(e_hat - c.e_m);
      const double metal = c.e_m + fit_ggx_E_loss(mu, r, p) * ms_ratio - 1.0;  // white metal (F = 1)
      furnace_metal.add(metal);
      for (size_t b = 0; b + 1 < bands.size(); ++b)
        if (r >= bands[b] && r < bands[b + 1]) metal_band[b].add(metal);
      for (size_t k = 0; k < f0s.size(); ++k) {
        const double f0 = f0s[k];
        const double fms = fresnel_ms(f0, 1.0, avg[ir].e_avg);
        const double exact = f0 * c.e_m + (1 - f0) * c.e_5 + fms * (1 - c.e_m);
        const double b_hat = fit_base_E(mu, r, f0, p);
        be.add(b_hat - exact);
        // specular: M_r F (exact albedo) + F_ms(fitted E_avg) M_r,ms (built from the fits)
        const double spec = f0 * c.e_m + (1 - f0) * c.e_5 + fresnel_ms(f0, 1.0, ea_fit) * fit_ggx_E_loss(mu, r, p) * ms_ratio;
        const double ab = fit_base_E_avg(r, f0, p);
        const double diffuse = 1.0 - ab > 0 ? (1.0 - b_hat) * (1.0 - base_int[k]) / (1.0 - ab) : 0.0;
        furnace_diel.add(spec + diffuse - 1.0);
      }
    }
  }
  for (size_t i = 0; i < sheen.size(); ++i) {
    const double mu = mus[i % nmu], a = alphas[i / nmu];
    sb.add(fit_sheen_E(mu, a, p) - sheen[i].main);
    sa.add(fit_sheen_ash_E(mu, a, p) - sheen[i].ash);
    map_sb.push_back(fit_sheen_E(mu, a, p) - sheen[i].main);
  }
  nlohmann::json out;
  out["grid"] = {{"roughness", {{"kind", "0, 0.01, 1, geometric on [0.01, 0.1) offset 0.37, cell offset 0.27"}, {"n", rs.size()}}},
                 {"cos_theta", {{"kind", "mu_min, 1, geometric below 0.1 from mu_min, uniform above, offset 0.27"},
                                {"lo", s.mu_min},
                                {"n", mus.size()}}},
                 {"f0", f0s},
                 {"alpha_b", {{"kind", "geometric offset 0.37 plus the lower end"}, {"lo", s.alpha_b_min}, {"hi", 1.0},
                              {"n", alphas.size()}}},
                 {"reference", {{"quadrature", "validate/lut_reference.h (Gauss-Legendre over h)"}, {"panels", s.panels}}}};
  out["ggx_E"] = em.to_json();
  out["ggx_E_avg"] = ea.to_json();
  out["base_E"] = be.to_json();
  out["base_E_avg"] = ba.to_json();
  out["sheen_E"] = sb.to_json();
  out["sheen_ash_E"] = sa.to_json();
  out["consistency"] = {{"ggx_E_avg_minus_cosine_average_of_fitted_ggx_E", cons_avg.to_json()},
                        {"ggx_E_avg_loss_relative_to_cosine_average_of_fitted_loss", cons_loss.to_json()},
                        {"ggx_E5_avg_minus_cosine_average_of_fitted_ggx_E5", cons_5avg.to_json()}};
  out["white_furnace_metal"] = furnace_metal.to_json();
  out["white_furnace_dielectric"] = furnace_diel.to_json();
  out["maps"]["ggx_E"] = {{"roughness", rs}, {"cos_theta", mus}, {"error", map_em}};
  out["maps"]["sheen_E"] = {{"alpha_b", alphas}, {"cos_theta", mus}, {"error", map_sb}};
  for (size_t b = 0; b + 1 < bands.size(); ++b)
    out["white_furnace_metal_bands"].push_back(
        {{"roughness", {bands[b], std::min(1.0, bands[b + 1])}}, {"error", metal_band[b].to_json()}});
  return out;
}

}  // namespace dspbr::fit
