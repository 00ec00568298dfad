#include "dspbr/fit/albedo_fit.h"

#include <algorithm>

#include "dspbr/fresnel.h"
#include "dspbr/lut/albedo.h"
#include "dspbr/lut/lut_set.h"
#include "dspbr/quadrature.h"

namespace dspbr::fit {

namespace {

struct EavgResidual {  // absolute error of E_m,avg (a relative fit of the loss did worse)
  double x, target;
  template <class T>
  bool operator()(const T* q, T* r) const {
    r[0] = ggx_e_avg_form<T>(q, x) - T(target);
    return true;
  }
};
struct DualResidual {  // S(x; y1, y2) - target
  double x, y1, y2, target;
  template <class T>
  bool operator()(const T* q, T* r) const {
    r[0] = dual_poly2<T>(q, x, y1, y2) - T(target);
    return true;
  }
};
struct P1Residual {
  double x, target;
  template <class T>
  bool operator()(const T* q, T* r) const {
    r[0] = poly1<T>(q, x) - T(target);
    return true;
  }
};

IntegratorSettings integrator(const AlbedoFitSettings& s, const FitContext& ctx) {
  IntegratorSettings is;
  is.samples = s.samples;
  is.randomizations = 8;
  is.seed = ctx.seed;
  return is;
}

// Exact references at (mu, r): E_m, E_5 (see albedo_forms.h) from lut/albedo.h.
struct GgxRef {
  double e_m, e_5;
};
// E_m,avg(r) and E_5,avg(r).
struct GgxAvgRef {
  double e_avg, e5_avg;
};

GgxAvgRef ggx_avg_ref(double r, const IntegratorSettings& is, uint64_t stream) {
  Estimate e_avg;
  const auto base = base_E_avg_f0s(r, {0.0}, is, stream, &e_avg);
  // base E_avg(r, 0) = E_5,avg + F_ms(0, 1) (1 - E_m,avg)
  return {e_avg.value, base[0].value - fresnel_ms(0.0, 1.0, e_avg.value) * (1.0 - e_avg.value)};
}

GgxRef ggx_ref(double mu, double r, double e_avg, const IntegratorSettings& is, uint64_t stream) {
  const Estimate em = ggx_E(mu, r, is, stream);
  const auto base = base_E_f0s(mu, r, {0.0}, Estimate{e_avg, 0.0}, is, stream);
  // base E(mu; r, 0) = E_5 + F_ms(0, 1) (1 - E_m), same integration samples for E_m? no: separate
  // estimates, so E_5 carries both QMC errors (~5e-5 at 16384 samples).
  return {em.value, base[0].value - fresnel_ms(0.0, 1.0, e_avg) * (1.0 - em.value)};
}

// Fit grid in roughness: cell-centred on [0, 1].
std::vector<double> r_grid(int n, double offset) {
  std::vector<double> g;
  for (int i = 0; i < n; ++i) g.push_back((i + offset) / n);
  return g;
}

// 2 Integral_0^1 f(mu) mu dmu by Gauss-Legendre (used on the fitted E_m for the furnace test).
template <class F>
double hemispherical_average(F&& f) {
  static const QuadratureRule rule = gauss_legendre(16);
  return integrate_gl([&](double mu) { return 2.0 * f(mu) * mu; }, 0.0, 1.0, 16, rule);
}

}  // namespace

AlbedoFitParams albedo_fit_start() {
  AlbedoFitParams p;
  p.ggx_E[0] = 1.0;
  p.ggx_E_avg[0] = 0.5;
  p.ggx_E5[0] = 0.1;
  p.ggx_E5_avg[0] = 0.1;
  p.sheen_E[0] = 0.5;
  return p;
}

AlbedoFitResult fit_albedos(const AlbedoFitSettings& s, const FitContext& ctx) {
  const IntegratorSettings is = integrator(s, ctx);
  // Cell-centred grids plus the domain edges r = 0, 1 and mu = 1 (no extrapolation at the corners).
  auto rs = r_grid(s.n_r, 0.5);
  rs.insert(rs.begin(), 0.0);
  rs.push_back(1.0);
  auto mus = cosine_grid(0.002, 1.0, s.n_mu, 0.5);
  mus.push_back(1.0);
  // Averages: one per roughness row (also needed by E_5).
  const auto avg = parallel_map<GgxAvgRef>(ctx, rs.size(), [&](size_t i) { return ggx_avg_ref(rs[i], is, 1000003 + i); });
  // (rs holds the end points r = 0 and 1: they keep the polynomials of the averages tame there.)
  const auto ref = parallel_map<GgxRef>(ctx, rs.size() * mus.size(), [&](size_t i) {
    const size_t ir = i / mus.size();
    return ggx_ref(mus[i % mus.size()], rs[ir], avg[ir].e_avg, is, 2000003 + i);
  });
  const auto alphas = geometric_grid(s.alpha_b_min, 1.0, s.n_r);
  const auto sheen = parallel_map<double>(ctx, alphas.size() * mus.size(), [&](size_t i) {
    return sheen_E(mus[i % mus.size()], alphas[i / mus.size()], SheenModel::Main, is, 3000003 + i).value;
  });
  AlbedoFitResult out;
  out.params = albedo_fit_start();
  std::vector<DualResidual> em, e5, sb;
  std::vector<EavgResidual> ea;
  std::vector<P1Residual> e5a;
  for (size_t ir = 0; ir < rs.size(); ++ir) {
    ea.push_back({rs[ir], avg[ir].e_avg});
    e5a.push_back({rs[ir], avg[ir].e5_avg});
    for (size_t j = 0; j < mus.size(); ++j) {
      const double u = ggx_albedo_u(mus[j], rs[ir]);
      em.push_back({rs[ir], u, mus[j], ref[ir * mus.size() + j].e_m});
      e5.push_back({rs[ir], mus[j], u, ref[ir * mus.size() + j].e_5});
    }
  }
  for (size_t ia = 0; ia < alphas.size(); ++ia)
    for (size_t j = 0; j < mus.size(); ++j)
      sb.push_back({sheen_e_l(alphas[ia]), std::sqrt(mus[j]), sheen_e_u(mus[j], alphas[ia]),
                    sheen[ia * mus.size() + j]});
  out.ggx_E = fit_minimax<kDualParams>(em, out.params.ggx_E, s.minimax);
  out.ggx_E_avg = fit_minimax<kPoly1Params>(ea, out.params.ggx_E_avg, s.minimax);
  out.ggx_E5 = fit_minimax<kDualParams>(e5, out.params.ggx_E5, s.minimax);
  out.ggx_E5_avg = fit_minimax<kPoly1Params>(e5a, out.params.ggx_E5_avg, s.minimax);
  // Sheen: one more Lawson round (its error concentrates at grazing, small alpha_b).
  MinimaxOptions sheen_opt = s.minimax;
  sheen_opt.lawson_rounds += 1;
  out.sheen_E = fit_minimax<kDualParams>(sb, out.params.sheen_E, sheen_opt);
  return out;
}

nlohmann::json albedo_report(const AlbedoFitSettings& s, const AlbedoFitParams& p, const FitContext& ctx) {
  const IntegratorSettings is = integrator(s, ctx);
  // Fresh grids: offsets and sizes differ from the fit grids; r = 0 and 1, mu = 1 included.
  const int nr = ctx.quick ? 7 : 29, nm = ctx.quick ? 9 : 37;
  auto rs = r_grid(nr, 0.27);
  rs.push_back(0.0);
  rs.push_back(1.0);
  auto mus = cosine_grid(0.002, 1.0, nm, 0.27);
  mus.push_back(1.0);
  const std::vector<double> f0s = ctx.quick ? std::vector<double>{0.0, 0.5, 1.0}
                                            : std::vector<double>{0.0, 0.02, 0.04, 0.1, 0.25, 0.5, 0.75, 1.0};
  struct AvgRow {
    double e_avg;
    std::vector<double> base_avg;
  };
  const auto avg = parallel_map<AvgRow>(ctx, rs.size(), [&](size_t i) {
    Estimate e;
    const auto b = base_E_avg_f0s(rs[i], f0s, is, 5000011 + i, &e);
    AvgRow row{e.value, {}};
    for (const auto& x : b) row.base_avg.push_back(x.value);
    return row;
  });
  struct Cell {
    double e_m;
    std::vector<double> base;
  };
  const auto cells = parallel_map<Cell>(ctx, rs.size() * mus.size(), [&](size_t i) {
    const size_t ir = i / mus.size();
    const double mu = mus[i % mus.size()], r = rs[ir];
    Cell c{ggx_E(mu, r, is, 6000011 + i).value, {}};
    for (const auto& x : base_E_f0s(mu, r, f0s, Estimate{avg[ir].e_avg, 0.0}, is, 7000011 + i)) c.base.push_back(x.value);
    return c;
  });
  const auto alphas = geometric_grid(s.alpha_b_min, 1.0, nr);
  const auto sheen = parallel_map<double>(ctx, alphas.size() * mus.size(), [&](size_t i) {
    return sheen_E(mus[i % mus.size()], alphas[i / mus.size()], SheenModel::Main, is, 8000011 + i).value;
  });
  ErrorStats em, ea, be, ba, sb, furnace;
  std::vector<double> map_em, map_sb;  // signed errors on the fresh grid (plots)
  const std::vector<double> furnace_edges = {0.05, 0.25, 0.5, 1.0 + 1e-9};
  std::vector<ErrorStats> furnace_band(furnace_edges.size() - 1), furnace_lut_band(furnace_edges.size() - 1);
  // Baseline: the same furnace with the committed published-layout tables (bilinear GGX_E,
  // linear GGX_E_avg).
  const LutSet& lut = LutSet::published();
  for (size_t ir = 0; ir < rs.size(); ++ir) {
    const double r = rs[ir];
    ea.add(fit_ggx_E_avg(r, p) - avg[ir].e_avg);
    for (size_t k = 0; k < f0s.size(); ++k) ba.add(fit_base_E_avg(r, f0s[k], p) - avg[ir].base_avg[k]);
    // White metal (f0 = f90 = 1) with the fitted E_m, E_m,avg in M_r,ms: albedo =
    // E_m(mu) + (1 - E^(mu)) (1 - 2 Int E^ mu dmu) / (1 - E^_avg); 1 with exact tables.
    const double e_hat_int = hemispherical_average([&](double m) { return fit_ggx_E(m, r, p); });
    const double e_hat_avg = fit_ggx_E_avg(r, p);
    const double e_lut_int = hemispherical_average([&](double m) { return lut.E_m(m, r); });
    const double e_lut_avg = lut.E_m_avg(r);
    for (size_t j = 0; j < mus.size(); ++j) {
      const Cell& c = cells[ir * mus.size() + j];
      em.add(fit_ggx_E(mus[j], r, p) - c.e_m);
      map_em.push_back(fit_ggx_E(mus[j], r, p) - c.e_m);
      for (size_t k = 0; k < f0s.size(); ++k) be.add(fit_base_E(mus[j], r, f0s[k], p) - c.base[k]);
      // r -> 0: 1 - E_avg -> 0 and the compensation vanishes; skip r < 0.05 where both the
      // fitted ratio and the exact one are 0/0 limits (the lobe there is a mirror: albedo 1).
      if (r >= 0.05) {
        const double ms = (1.0 - fit_ggx_E(mus[j], r, p)) * (1.0 - e_hat_int) / std::max(1e-12, 1.0 - e_hat_avg);
        furnace.add(c.e_m + ms - 1.0);
        const double ms_lut = (1.0 - lut.E_m(mus[j], r)) * (1.0 - e_lut_int) / std::max(1e-12, 1.0 - e_lut_avg);
        for (size_t b = 0; b + 1 < furnace_edges.size(); ++b)
          if (r >= furnace_edges[b] && r < furnace_edges[b + 1]) {
            furnace_band[b].add(c.e_m + ms - 1.0);
            furnace_lut_band[b].add(c.e_m + ms_lut - 1.0);
          }
      }
    }
  }
  for (size_t i = 0; i < sheen.size(); ++i) {
    sb.add(fit_sheen_E(mus[i % mus.size()], alphas[i / mus.size()], p) - sheen[i]);
    map_sb.push_back(fit_sheen_E(mus[i % mus.size()], alphas[i / mus.size()], p) - sheen[i]);
  }
  nlohmann::json out;
  out["grid"] = {{"roughness", {{"kind", "cell offset 0.27, plus 0 and 1"}, {"n", rs.size()}}},
                 {"cos_theta", {{"kind", "geometric below 0.1 from 0.002, uniform above, offset 0.27, plus 1"},
                                {"n", mus.size()}}},
                 {"f0", f0s},
                 {"alpha_b", {{"kind", "geometric"}, {"lo", s.alpha_b_min}, {"hi", 1.0}, {"n", nr}}},
                 {"reference", {{"integrator", "qmc"}, {"samples", s.samples}, {"seed", ctx.seed}}}};
  out["ggx_E"] = em.to_json();
  out["ggx_E_avg"] = ea.to_json();
  out["base_E"] = be.to_json();
  out["base_E_avg"] = ba.to_json();
  out["sheen_E"] = sb.to_json();
  out["white_furnace_metal"] = furnace.to_json();
  out["maps"]["ggx_E"] = {{"roughness", rs}, {"cos_theta", mus}, {"error", map_em}};
  out["maps"]["sheen_E"] = {{"alpha_b", alphas}, {"cos_theta", mus}, {"error", map_sb}};
  for (size_t b = 0; b < furnace_band.size(); ++b)
    out["white_furnace_metal_bands"].push_back(
        {{"roughness", {furnace_edges[b], std::min(1.0, furnace_edges[b + 1])}},
         {"error", furnace_band[b].to_json()},
         {"error_with_tables", furnace_lut_band[b].to_json()}});
  return out;
}

}  // namespace dspbr::fit
