#include "dspbr/validate/suite.h"

#include "dspbr/io/json_write.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <limits>
#include <map>
#include <tbb/global_control.h>
#include <ctime>

#include "dspbr/frame.h"
#include "dspbr/io/atomic_file.h"
#include "dspbr/io/json_values.h"
#include "dspbr/tables/table_registry.h"
#include "dspbr/progress.h"
#include "dspbr/validate/furnace_image.h"
#include "dspbr/validate/integrator_study.h"
#include "dspbr/validate/provenance.h"
#include "dspbr/validate/waivers.h"

namespace dspbr::validate {

using nlohmann::json;

namespace {

const char* claim_name(EnergyClaim c) {
  switch (c) {
    case EnergyClaim::Preserving: return "preserving";
    case EnergyClaim::GainsBySpec: return "gains_by_spec";
    default: return "conserving";
  }
}

constexpr double kNoView = std::numeric_limits<double>::quiet_NaN();

// Worst first: FAIL > WAIVED > PASS > NOT JUDGED (a judged verdict outweighs an unjudged one:
// a case whose grazing rows are not judged and whose other rows pass is PASS).
int rank(Status s) {
  switch (s) {
    case Status::Fail: return 3;
    case Status::Waived: return 2;
    case Status::NotJudged: return 0;
    default: return 1;
  }
}

const char* kNoPowerReason =
    "the band (±sigmas standard errors of the narrower estimator) is wider than the tolerance: the check could not "
    "have failed a violation of the tolerance (band and tolerance per row in the furnace tables)";

// Verdict bookkeeping: per check name, counts of each status; a line for every verdict that is not
// PASS; failed verdicts matched against the waivers (waivers.h).
struct Verdicts {
  struct Count { int passed = 0, failed = 0, waived = 0, not_judged = 0; };
  const LutSet* luts = nullptr;
  std::map<std::string, Count> counts;
  std::vector<std::string> failures, waived;
  json listed = json::array();
  std::vector<int> waiver_uses = std::vector<int>(dspbr_waivers().size(), 0);
  std::string prefix;  // before each check's name (another implementation's verdicts); waivers match the name alone

  static std::string where(const std::string& name, double cos) {
    return std::isfinite(cos) ? fmt::format("{} at cos={}", name, cos) : name;
  }
  // A judged verdict on case `name` (at view cosine `cos`, or kNoView). Returns its status.
  Status add(const std::string& check_name, bool ok, const std::string& name, double cos, const std::string& detail) {
    const std::string check = prefix + check_name;
    Count& c = counts[check];
    const std::string what = where(name, cos) + ": " + detail;
    if (ok) {
      ++c.passed;
      return Status::Pass;
    }
    const auto& ws = dspbr_waivers();
    for (std::size_t k = 0; k < ws.size(); ++k)
      if (waiver_applies(ws[k], check_name, name, cos, luts)) {
        ++c.waived;
        ++waiver_uses[k];
        waived.push_back(check + ": " + what + " [waiver " + ws[k].id + "]");
        listed.push_back({{"check", check}, {"what", what}, {"status", status_word(Status::Waived)},
                          {"waiver", ws[k].id}});
        return Status::Waived;
      }
    ++c.failed;
    failures.push_back(check + ": " + what);
    listed.push_back({{"check", check}, {"what", what}, {"status", status_word(Status::Fail)}});
    return Status::Fail;
  }
  // A furnace bound at one direction (furnace.h): PASS, FAIL (waivers apply) or NOT JUDGED with
  // the reason its band gives.
  Status judge(const std::string& check, const BoundVerdict& b, const std::string& name, double cos,
               const std::string& detail) {
    if (b.decision == Decision::NotJudged) return not_judged(check, name, cos, detail, kNoPowerReason);
    return add(check, b.decision == Decision::Pass, name, cos, detail);
  }
  // A verdict the run does not judge (the numbers are still reported), with the reason.
  Status not_judged(const std::string& check_name, const std::string& name, double cos, const std::string& detail,
                    const std::string& reason) {
    const std::string check = prefix + check_name;
    ++counts[check].not_judged;
    listed.push_back({{"check", check}, {"what", where(name, cos) + ": " + detail},
                      {"status", status_word(Status::NotJudged)}, {"reason", reason}});
    return Status::NotJudged;
  }
};

// ---------------------------------------------------------------- white furnace

Status status_from(const json& word) {
  for (Status s : {Status::Pass, Status::Fail, Status::NotJudged, Status::Waived})
    if (word == status_word(s)) return s;
  return Status::Pass;
}

// The sample count at which a bound's band (~ 1/sqrt(n)) would fit its tolerance, from its band at n.
double samples_for_power(const BoundVerdict& b, std::size_t n) {
  return double(n) * (b.band / b.tolerance) * (b.band / b.tolerance);
}

json run_energy(const Catalog& cat, const SuiteSettings& s, Verdicts& verdicts) {
  struct Item { std::size_t c; double cos; };
  std::vector<Item> items;
  for (std::size_t c = 0; c < cat.cases.size(); ++c) {
    for (double x : s.furnace_cos) items.push_back({c, x});
    if (cat.cases[c].viewer_below)
      for (double x : s.furnace_cos) items.push_back({c, -x});
  }
  struct Out { QuadratureAlbedo quad; SampledAlbedo sampled; EnergyVerdict verdict; };
  std::vector<Out> out(items.size());
  Progress progress("white furnace", items.size(), s.progress && Progress::stderr_is_terminal());
  tbb::parallel_for(std::size_t(0), items.size(), [&](std::size_t i) {
    const BsdfCase& bc = cat.cases[items[i].c];
    const Vec3 v = view_dir(items[i].cos);
    EnergyTolerances tol = s.energy;
    if (bc.preservation_tol >= 0) tol.preservation = bc.preservation_tol;
    const double eta_ratio = v.z >= 0 ? bc.eta_above / bc.eta_below : bc.eta_below / bc.eta_above;
    out[i].quad = albedo_quadrature(*bc.bsdf, v, eta_ratio, s.furnace_quadrature_tolerance,
                                    bc.cones ? bc.cones(v) : std::vector<FeatureCone>{});
    // The sampled estimator's count grows (from a stream of its own each round) while a verdict of
    // the row is NOT JUDGED for its band: to the count at which the band would fit the tolerance
    // (band ~ 1/sqrt(n), times 1.5, in powers of 4), when that is within furnace_samples_max.
    for (std::size_t n = s.furnace_samples, round = 0;; ++round) {
      out[i].sampled = albedo_sampled(*bc.bsdf, v, n, s.seed, 2 * i + 1 + 1000000 * round);
      out[i].verdict = judge_energy(out[i].quad, out[i].sampled, tol);
      const EnergyVerdict& e = out[i].verdict;
      double needed = 0;  // samples for the verdicts without power, times 1.5
      for (const BoundVerdict* b : {&e.agreement, &e.conservation, &e.preservation}) {
        if (b == &e.preservation && bc.claim != EnergyClaim::Preserving) continue;
        if (b->decision == Decision::NotJudged) needed = std::max(needed, 1.5 * samples_for_power(*b, n));
      }
      if (needed == 0) break;
      std::size_t next = 4 * n;
      while (double(next) < needed) next *= 4;
      if (next > s.furnace_samples_max) break;
      n = next;
    }
    progress.add();
  });
  progress.finish();
  json rows = json::array();
  std::vector<json> per_case(cat.cases.size());
  // A bound without power at the sampled estimator's cap says what would give it power.
  const std::size_t full_run_cap = SuiteSettings::defaults(false).furnace_samples_max;
  auto bound_json = [&s, full_run_cap](const BoundVerdict& b, Status st, std::size_t samples) {
    json j = {{"status", status_word(st)}, {"value", b.value}, {"band", b.band}, {"tolerance", b.tolerance},
              {"estimator", b.estimator}};
    if (b.decision == Decision::NotJudged)
      j["reason"] = fmt::format("{} with {} samples: the band would fit at about {:.2g} samples, beyond this run's cap "
                                "{} (the sampled weights are heavy-tailed here; the full run's cap is {})",
                                b.reason(), samples, samples_for_power(b, samples), s.furnace_samples_max, full_run_cap);
    return j;
  };
  auto bound_detail = [](const char* what, const BoundVerdict& b) {
    return fmt::format("{} {:.5f} ± {:.2g} ({}; tolerance {:g})", what, b.value, b.band, b.estimator, b.tolerance);
  };
  for (std::size_t i = 0; i < items.size(); ++i) {
    const BsdfCase& bc = cat.cases[items[i].c];
    const Out& o = out[i];
    const double n = double(o.sampled.total.samples);
    rows.push_back({{"case", bc.name}, {"cos", items[i].cos},
                    {"quadrature", rgb_json(o.quad.value)}, {"quadrature_error", o.quad.error},
                    {"quadrature_evaluations", o.quad.evaluations}, {"samples", o.sampled.total.samples},
                    {"sampled", rgb_json(o.sampled.total.value)}, {"sampled_se", rgb_json(o.sampled.total.std_error)},
                    {"non_delta", rgb_json(o.sampled.non_delta.value)},
                    {"non_delta_se", rgb_json(o.sampled.non_delta.std_error)},
                    {"delta", rgb_json(o.sampled.delta.value)}, {"delta_se", rgb_json(o.sampled.delta.std_error)},
                    {"invalid_fraction", n > 0 ? double(o.sampled.invalid) / n : 0.0}});
    json& pc = per_case[items[i].c];
    const double lo = o.verdict.albedo_min, hi = o.verdict.albedo_max;
    if (pc.is_null()) pc = {{"min", lo}, {"max", hi}, {"views", 0}, {"judged_views", 0}};
    pc["min"] = std::min(pc["min"].get<double>(), lo);
    pc["max"] = std::max(pc["max"].get<double>(), hi);
    pc["views"] = pc["views"].get<int>() + 1;
    const double x = items[i].cos;
    const std::string agree_detail = fmt::format("quadrature {:.5f} vs sampled (non-delta, {} samples) {:.5f}: {}",
                                                 o.quad.value.max_component(), o.sampled.total.samples,
                                                 o.sampled.non_delta.value.max_component(),
                                                 bound_detail("|difference|", o.verdict.agreement));
    const Status agree = verdicts.judge("furnace: estimators agree", o.verdict.agreement, bc.name, x, agree_detail);
    const Status cons = verdicts.judge("furnace: conservation (E <= 1 + tol)", o.verdict.conservation, bc.name, x,
                                       bound_detail("albedo", o.verdict.conservation));
    json vj = {{"agreement", status_word(agree)}, {"conservation", status_word(cons)}};
    const std::size_t samples = o.sampled.total.samples;
    json judged = {{"agreement", bound_json(o.verdict.agreement, agree, samples)},
                   {"conservation", bound_json(o.verdict.conservation, cons, samples)}};
    if (bc.claim == EnergyClaim::Preserving) {
      const Status pres = verdicts.judge("furnace: preservation where claimed (E >= 1 - tol)", o.verdict.preservation,
                                         bc.name, x, bound_detail("albedo", o.verdict.preservation));
      vj["preservation"] = status_word(pres);
      judged["preservation"] = bound_json(o.verdict.preservation, pres, samples);
    }
    rows.back()["verdicts"] = vj;
    rows.back()["judged"] = judged;
    // The albedo range measured with power (the conservation band within its tolerance, hence
    // the preservation band too): the only values the report attributes to DSPBR itself.
    if (o.verdict.conservation.decision != Decision::NotJudged) {
      const double jlo = o.verdict.preservation.value, jhi = o.verdict.conservation.value;
      pc["judged_views"] = pc["judged_views"].get<int>() + 1;
      pc["judged_min"] = pc.contains("judged_min") ? std::min(pc["judged_min"].get<double>(), jlo) : jlo;
      pc["judged_max"] = pc.contains("judged_max") ? std::max(pc["judged_max"].get<double>(), jhi) : jhi;
    }
    // Per case: the worst status of each check over its view directions, and the unjudged counts.
    // ... and, so that a case's PASS says how much it rests on, the views judged and the unjudged
    // views whose estimate lies beyond the tolerance anyway (marked in the report).
    for (const auto& [k, word] : vj.items()) {
      if (!pc.contains(k) || rank(status_from(word)) > rank(status_from(pc[k]))) pc[k] = word;
      if (word == status_word(Status::NotJudged)) {
        pc[k + "_not_judged"] = pc.value(k + "_not_judged", 0) + 1;
        const BoundVerdict& b = k == "conservation"   ? o.verdict.conservation
                                : k == "preservation" ? o.verdict.preservation
                                                      : o.verdict.agreement;
        if (b.beyond) pc[k + "_unjudged_beyond"] = pc.value(k + "_unjudged_beyond", 0) + 1;
      } else {
        pc[k + "_judged"] = pc.value(k + "_judged", 0) + 1;
      }
    }
  }
  json cases = json::array();
  for (std::size_t c = 0; c < cat.cases.size(); ++c) {
    const BsdfCase& bc = cat.cases[c];
    json j = per_case[c];
    j["case"] = bc.name;
    j["component"] = bc.component;
    j["params"] = bc.params;
    j["claim"] = claim_name(bc.claim);
    j["preservation_tol"] = bc.preservation_tol >= 0 ? bc.preservation_tol : s.energy.preservation;
    j["note"] = bc.note;
    j["flags"] = bc.bsdf->flags();
    cases.push_back(j);
  }
  return {{"tolerances", {{"conservation", s.energy.conservation}, {"preservation", s.energy.preservation},
                          {"sigmas", s.energy.sigmas}, {"agreement_abs", s.energy.agreement_abs},
                          {"agreement_band_max", s.energy.agreement_band_max}}},
          {"quadrature_tolerance", s.furnace_quadrature_tolerance},
          {"samples", s.furnace_samples}, {"samples_max", s.furnace_samples_max}, {"cos", s.furnace_cos}, {"rows", rows}, {"cases", cases}};
}

// ---------------------------------------------------------------- reciprocity

json stats_json(const ReciprocityStats& st) {
  return {{"pairs", st.pairs}, {"max_rel_dev", st.max_rel_dev}, {"worst_v", vec_json(st.worst_v)},
          {"worst_l", vec_json(st.worst_l)}, {"worst_f_vl", st.worst_a}, {"worst_f_lv", st.worst_b}};
}

json run_reciprocity(const Catalog& cat, const SuiteSettings& s, Verdicts& verdicts) {
  std::vector<ReciprocityResult> res(cat.cases.size());
  Progress progress("reciprocity", cat.cases.size(), s.progress && Progress::stderr_is_terminal());
  tbb::parallel_for(std::size_t(0), cat.cases.size(), [&](std::size_t c) {
    ReciprocitySettings rs;
    rs.pairs = s.reciprocity_pairs;
    rs.eta_above = cat.cases[c].eta_above;
    rs.eta_below = cat.cases[c].eta_below;
    rs.seed = s.seed + 1000003 * c;
    res[c] = reciprocity_check(*cat.cases[c].bsdf, rs);
    progress.add();
  });
  progress.finish();
  json arr = json::array();
  for (std::size_t c = 0; c < cat.cases.size(); ++c) {
    const BsdfCase& bc = cat.cases[c];
    const ReciprocityResult& r = res[c];
    const double refl = std::max(r.reflection_upper.max_rel_dev, bc.viewer_below ? r.reflection_lower.max_rel_dev : 0.0);
    const double trans = bc.adjoint_eta_rule ? r.transmission_adjoint.max_rel_dev : r.transmission_eta2.max_rel_dev;
    const bool ok = (refl <= s.reciprocity_tol && trans <= s.reciprocity_tol);
    const std::string detail = fmt::format("reflection {:.3g}, transmission ({} eta^2 rule) {:.3g}, (plain) {:.3g}",
                                           refl, bc.adjoint_eta_rule ? "adjoint" : "radiance", trans,
                                           r.transmission_plain.max_rel_dev);
    const Status st = bc.non_reciprocal_by_design
                          ? verdicts.not_judged("reciprocity (reflection; eta^2 rule for refraction)", bc.name, kNoView,
                                                detail, bc.non_reciprocal_reason)
                          : verdicts.add("reciprocity (reflection; eta^2 rule for refraction)", ok, bc.name, kNoView, detail);
    arr.push_back({{"case", bc.name}, {"component", bc.component}, {"eta_above", bc.eta_above},
                   {"eta_below", bc.eta_below}, {"reflection_upper", stats_json(r.reflection_upper)},
                   {"reflection_lower", stats_json(r.reflection_lower)},
                   {"transmission_eta2", stats_json(r.transmission_eta2)},
                   {"transmission_plain", stats_json(r.transmission_plain)},
                   {"transmission_adjoint", stats_json(r.transmission_adjoint)},
                   {"eta_rule", bc.adjoint_eta_rule ? "adjoint" : "radiance"}, {"passed", ok},
                   {"verdict", status_word(st)},
                   {"non_reciprocal_by_design", bc.non_reciprocal_by_design},
                   {"reason", bc.non_reciprocal_reason}});
  }
  return {{"pairs", s.reciprocity_pairs}, {"tolerance", s.reciprocity_tol}, {"cases", arr}};
}

// ---------------------------------------------------------------- chi-square

json run_chi2(const Catalog& cat, const SuiteSettings& s, Verdicts& verdicts) {
  struct Item { std::size_t c; double cos; };
  std::vector<Item> items;
  for (std::size_t c = 0; c < cat.cases.size(); ++c) {
    if (!cat.cases[c].chi2) continue;
    for (double x : s.chi2_cos) items.push_back({c, x});
    if (cat.cases[c].viewer_below)
      for (double x : s.chi2_cos_below) items.push_back({c, x});
  }
  // Histograms kept for a few tests spread over the list.
  std::vector<bool> keep(items.size(), false);
  for (std::size_t k = 0; k < std::min(s.chi2_histograms, items.size()); ++k)
    keep[k * items.size() / std::min(s.chi2_histograms, items.size())] = true;
  json tests = json::array(), hists = json::array();
  Progress progress("chi-square", items.size(), s.progress && Progress::stderr_is_terminal());
  for (std::size_t i = 0; i < items.size(); ++i) {  // each test is parallel inside
    const BsdfCase& bc = cat.cases[items[i].c];
    Chi2Settings cs = s.chi2;
    cs.seed = s.seed;
    cs.stream = i;
    cs.num_tests = int(items.size());
    cs.keep_histograms = keep[i];
    const Chi2Result r = chi2_test(*bc.bsdf, view_dir(items[i].cos), cs);
    progress.add();
    const double x = items[i].cos;
    const Status st[] = {
        verdicts.add("sampling: chi-square goodness of fit", r.chi2_passed, bc.name, x,
                     fmt::format("p = {:.3g} < {:.3g} (chi2 {:.1f}, dof {})", r.p_value, r.alpha, r.statistic, r.dof)),
        verdicts.add("sampling: no samples outside the pdf's support", r.support_passed, bc.name, x,
                     fmt::format("{} outside, {} non-finite", r.outside_support, r.non_finite)),
        verdicts.add("sampling: pdf integrates to 1 - P(delta) - P(fail)", r.integral_passed, bc.name, x,
                     fmt::format("integral {:.5f}, expected {:.5f} +- {:.5f}", r.pdf_integral, r.pdf_integral_expected,
                                 r.pdf_integral_tol)),
        verdicts.add("sampling: pdf and weight consistent with eval", r.consistency_passed, bc.name, x,
                     fmt::format("{} pdf / {} weight mismatches (max rel dev {:.3g} / {:.3g})", r.pdf_mismatches,
                                 r.weight_mismatches, r.max_pdf_rel_dev, r.max_weight_rel_dev))};
    Status worst = Status::Pass;
    for (Status t : st)
      if (rank(t) > rank(worst)) worst = t;
    tests.push_back({{"case", bc.name}, {"component", bc.component}, {"cos", items[i].cos},
                     {"statistic", r.statistic}, {"dof", r.dof}, {"p_value", r.p_value}, {"alpha", r.alpha},
                     {"pooled_bins", r.pooled_bins}, {"samples", r.samples}, {"invalid", r.invalid},
                     {"delta", r.delta}, {"outside_support", r.outside_support}, {"non_finite", r.non_finite},
                     {"pdf_integral", r.pdf_integral}, {"pdf_integral_expected", r.pdf_integral_expected},
                     {"pdf_integral_tol", r.pdf_integral_tol}, {"max_pdf_rel_dev", r.max_pdf_rel_dev},
                     {"max_weight_rel_dev", r.max_weight_rel_dev}, {"chi2_passed", r.chi2_passed},
                     {"support_passed", r.support_passed}, {"integral_passed", r.integral_passed},
                     {"consistency_passed", r.consistency_passed}, {"passed", r.passed()},
                     {"verdict", status_word(worst)}});
    if (keep[i]) {
      std::vector<float> o(r.observed.begin(), r.observed.end()), e(r.expected.begin(), r.expected.end());
      hists.push_back({{"case", bc.name}, {"cos", items[i].cos}, {"theta_bins", r.theta_bins}, {"phi_bins", r.phi_bins},
                       {"observed", o}, {"expected", e}, {"p_value", r.p_value}});
    }
  }
  progress.finish();
  return {{"samples", s.chi2.samples}, {"theta_bins", s.chi2.theta_bins}, {"phi_bins", 2 * s.chi2.theta_bins},
          {"integration_order", s.chi2.integration_order}, {"min_expected", s.chi2.min_expected},
          {"significance", s.chi2.significance}, {"num_tests", items.size()},
          {"alpha_per_test", sidak_alpha(s.chi2.significance, int(items.size()))},
          {"tests", tests}, {"histograms", hists}};
}

// ---------------------------------------------------------------- stability

json run_stability(const Catalog& cat, const SuiteSettings& s, Verdicts& verdicts) {
  std::vector<StabilityCounts> res(cat.stability.size());
  Progress progress("stability", cat.stability.size(), s.progress && Progress::stderr_is_terminal());
  tbb::parallel_for(std::size_t(0), cat.stability.size(), [&](std::size_t i) {
    StabilitySettings ss = s.stability;
    ss.seed = s.seed;
    ss.stream = i;
    res[i] = stability_scan(*cat.stability[i].bsdf, ss);
    progress.add();
  });
  progress.finish();
  // Per component, in order of first appearance; corners with failures listed.
  std::vector<std::string> order;
  std::map<std::string, StabilityCounts> per;
  std::map<std::string, int> corners;
  std::map<std::string, json> bad;
  for (std::size_t i = 0; i < res.size(); ++i) {
    const StabilityCase& sc = cat.stability[i];
    if (!per.count(sc.component)) {
      order.push_back(sc.component);
      bad[sc.component] = json::array();
    }
    per[sc.component] += res[i];
    ++corners[sc.component];
    if (res[i].total_failures() > 0 || res[i].above_bound > 0)
      bad[sc.component].push_back({{"corner", sc.corner}, {"nan", res[i].nan}, {"inf", res[i].inf},
                                   {"negative", res[i].negative}, {"above_bound", res[i].above_bound},
                                   {"bad_direction", res[i].bad_direction}, {"max_weight", res[i].max_weight},
                                   {"max_weight_v", vec_json(res[i].max_weight_v)},
                                   {"max_weight_u", vec_json(res[i].max_weight_u)}});
  }
  json arr = json::array();
  for (const std::string& c : order) {
    const StabilityCounts& t = per[c];
    verdicts.add("stability: no NaN / Inf / negative values, unit directions", t.total_failures() == 0, c, kNoView,
                 fmt::format("{} NaN, {} Inf, {} negative, {} bad directions", t.nan, t.inf, t.negative, t.bad_direction));
    arr.push_back({{"component", c}, {"corners", corners[c]}, {"evaluations", t.evaluations}, {"nan", t.nan},
                   {"inf", t.inf}, {"negative", t.negative}, {"above_bound", t.above_bound},
                   {"bad_direction", t.bad_direction}, {"max_weight", t.max_weight}, {"failing_corners", bad[c]}});
  }
  return {{"weight_bound", s.stability.weight_bound}, {"random_directions", s.stability.random_directions},
          {"components", arr}};
}

// ---------------------------------------------------------------- tables

// Indices spread over [0, n): all when n <= k.
std::vector<int> spread(int n, int k) {
  std::vector<int> out;
  if (n <= k) {
    for (int i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  for (int i = 0; i < k; ++i) out.push_back(int(std::lround(double(i) * (n - 1) / (k - 1))));
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// One checked node of a table: its indices, its point in physical coordinates, the value the
// BSDF reads there (decoded) and the table's own standard error (0 when not stored).
struct TableNode {
  std::vector<int> index;
  std::vector<double> x;  // the axes' physical coordinates, slowest first
  TablePoint point;
  double value = 0, se = 0;
};

// Cells: a spread of indices per axis, all combinations.
std::vector<std::vector<int>> spread_cells(const std::vector<int>& sizes, int per_axis) {
  std::vector<std::vector<int>> cells{{}};
  for (int n : sizes) {
    std::vector<std::vector<int>> next;
    for (const auto& c : cells)
      for (int i : spread(n, per_axis)) {
        auto d = c;
        d.push_back(i);
        next.push_back(d);
      }
    cells = next;
  }
  return cells;
}

// Sets the coordinate of axis `name` in p (the published and renderer axis names).
void set_coord(TablePoint& p, const std::string& name, double v) {
  if (name == "roughness") p.roughness = v;
  else if (name == "cos_theta") p.mu = v;
  else if (name == "alpha_b") p.alpha_b = v;
  else if (name == "f0") p.f0 = v;
  else if (name == "ior") p.ior = v;
  else if (name == "ior_x") p.ior = glass_ior_of_x(v);
  else throw std::invalid_argument("table axis '" + name + "' has no physical coordinate");
}

// Nodes of a published-layout table: the stored values at cell centres (or endpoints).
std::vector<TableNode> published_nodes(const Table& t, int per_axis) {
  std::vector<int> sizes;
  for (const Axis& a : t.axes) sizes.push_back(a.size);
  std::vector<TableNode> out;
  for (const auto& idx : spread_cells(sizes, per_axis)) {
    TableNode n;
    n.index = idx;
    for (std::size_t a = 0; a < t.axes.size(); ++a) {
      n.x.push_back(t.axes[a].coord(idx[a]));
      set_coord(n.point, t.axes[a].name, n.x.back());
    }
    const std::size_t off = t.offset(idx);
    n.value = t.values[off];
    n.se = t.errors.empty() ? 0.0 : t.errors[off];
    out.push_back(n);
  }
  return out;
}

// Nodes of a renderer-layout table: the decoded quantity its lookups return at the sample
// positions (grid coordinates i / (N - 1); the warps of the cos and ior axes depend on the
// roughness and the cosine, so those are placed first).
std::vector<TableNode> renderer_nodes(const RendererLuts& R, Lut id, int per_axis) {
  const WarpedTable& t = R.table(id);
  std::vector<int> sizes;
  for (const WarpedAxis& a : t.axes) sizes.push_back(a.size);
  auto axis_of = [&](const char* name) {
    for (std::size_t a = 0; a < t.axes.size(); ++a)
      if (t.axes[a].name == name) return int(a);
    return -1;
  };
  std::vector<TableNode> out;
  for (const auto& idx : spread_cells(sizes, per_axis)) {
    TableNode n;
    n.index = idx;
    n.x.assign(t.axes.size(), 0.0);
    auto grid = [&](int a) { return double(idx[std::size_t(a)]) / (t.axes[std::size_t(a)].size - 1); };
    auto place = [&](int a, double aux) {
      if (a < 0) return;
      n.x[std::size_t(a)] = t.axes[std::size_t(a)].warp.from_grid(grid(a), aux);
      set_coord(n.point, t.axes[std::size_t(a)].name, n.x[std::size_t(a)]);
    };
    place(axis_of("roughness"), 0.0);
    place(axis_of("alpha_b"), 0.0);
    place(axis_of("cos_theta"), n.point.roughness * n.point.roughness);
    place(axis_of("ior"), n.point.mu);
    place(axis_of("ior_x"), 0.0);
    const TablePoint& p = n.point;
    const bool inside = lut_info(id).inside;
    switch (id) {
      case Lut::GgxE: n.value = R.E_m(p.mu, p.roughness); break;
      case Lut::GgxBeta: n.value = R.B(p.mu, p.roughness); break;
      case Lut::GgxEAvg: n.value = R.E_m_avg(p.roughness); break;
      case Lut::GgxBAvg: n.value = R.B_avg(p.roughness); break;
      case Lut::SheenE: n.value = R.E_sheen(p.mu, p.alpha_b); break;
      case Lut::SheenAshE: n.value = R.E_sheen_ash(p.mu, p.alpha_b); break;
      case Lut::GlassE:
      case Lut::GlassInvE: n.value = R.E_glass(p.mu, p.roughness, p.ior, inside); break;
      case Lut::GlassEAvg:
      case Lut::GlassInvEAvg: n.value = R.E_glass_avg(p.roughness, p.ior, inside); break;
      default: throw std::invalid_argument(std::string("no renderer table '") + lut_name(id) + "'");
    }
    // GGX_beta's stored error is that of beta; the others' that of the quantity.
    std::size_t off = 0;  // row-major, fastest axis contiguous
    for (std::size_t a = 0; a < idx.size(); ++a) off = off * std::size_t(t.axes[a].size) + std::size_t(idx[a]);
    n.se = t.errors.empty() || id == Lut::GgxBeta ? 0.0 : t.errors[off];
    out.push_back(n);
  }
  return out;
}

// The table check: every table of the set the BSDF cases read (its layout's tables in registry
// order, the glass tables when the set holds them), each node's value against the reference
// (lut_reference.h) with the table's tolerance. Nodes at roughness 0 hold limits (r -> 0 at fixed
// mu / alpha in the renderer layout) and are not checked.
json run_luts(const LutSet* luts, const SuiteSettings& s, Verdicts& verdicts) {
  if (!luts) return {{"available", false}};
  const bool renderer = luts->layout == LutLayout::Renderer;
  const unsigned layout = renderer ? kRendererLayout : kPublishedLayout;
  json arr = json::array();
  for (const LutInfo& info : lut_registry()) {
    if ((info.layouts & layout) == 0) continue;
    std::vector<TableNode> nodes;
    json axes = json::array();
    json values;
    if (renderer) {
      if (info.glass && !luts->renderer.has_glass()) continue;
      const WarpedTable& t = luts->renderer.table(info.id);
      nodes = renderer_nodes(luts->renderer, info.id, s.lut_cells_per_axis);
      for (const WarpedAxis& a : t.axes)
        axes.push_back({{"name", a.name}, {"size", a.size}, {"warp", a.warp.describe()}, {"kind", "warped"}});
    } else {
      const Table& t = luts->published_table(info.id);
      if (t.values.empty()) continue;  // run_suite's caller refuses incomplete sets (missing_tables); glass optional
      nodes = published_nodes(t, s.lut_cells_per_axis);
      for (const Axis& a : t.axes)
        axes.push_back({{"name", a.name}, {"size", a.size}, {"lo", a.lo}, {"hi", a.hi},
                        {"kind", a.kind == GridKind::CellCentred ? "cell_centred" : "endpoint"}});
      values = t.values;
    }
    const bool has_r = std::any_of(info.axes.begin(), info.axes.end(), [](const char* a) { return std::string(a) == "roughness"; });
    nodes.erase(std::remove_if(nodes.begin(), nodes.end(),
                               [&](const TableNode& n) { return has_r && n.point.roughness <= 0.0; }),
                nodes.end());
    std::vector<RefValue> refs(nodes.size());
    const std::string label = fmt::format("{} ({})", info.name, renderer ? "renderer" : "published");
    // Renderer averages are cosine averages of the directional lookups (renderer_luts.h), so they
    // carry the directional tables' interpolation error: a tolerance of their own.
    const double tol = !renderer ? s.lut_tol : info.average ? s.renderer_avg_lut_tol : s.renderer_lut_tol;
    Progress progress("tables: " + label, nodes.size(), s.progress && Progress::stderr_is_terminal());
    tbb::parallel_for(std::size_t(0), nodes.size(), [&](std::size_t k) {
      // Power: the reference's own error must stay below half the tolerance, or the allowance
      // (tolerance + reference error) would let a table error beyond the tolerance pass. Doubling
      // the panels up to 3 times (the glass references have a fixed target, 1e-6).
      RefQuadrature q = s.lut_quadrature;
      refs[k] = table_quantity_ref(info.id, nodes[k].point, q);
      for (int more = 0; more < 3 && refs[k].error > 0.5 * tol && !info.glass; ++more) {
        q.panels *= 2;
        refs[k] = table_quantity_ref(info.id, nodes[k].point, q);
      }
      progress.add();
    });
    progress.finish();
    json jc = json::array();
    double max_err = 0, max_se = 0, max_ref_err = 0;
    bool ok = true;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const TableNode& n = nodes[k];
      // Relative where the exact value exceeds 1 (the main sheen's E_b at grazing), as --bench-lookups.
      const double err = std::abs(n.value - refs[k].value) / std::max(1.0, std::abs(refs[k].value));
      const double allowed = tol + refs[k].error;  // fixed: the table's own se never widens it
      max_err = std::max(max_err, err);
      max_se = std::max(max_se, n.se);
      max_ref_err = std::max(max_ref_err, refs[k].error);
      if (!(err <= allowed)) ok = false;
      jc.push_back({{"index", n.index}, {"x", n.x}, {"table", n.value}, {"table_se", n.se}, {"reference", refs[k].value},
                    {"reference_err", refs[k].error}, {"abs_error", err}, {"allowed", allowed}});
    }
    const char* check = "tables: LUT vs independent reference";
    const std::string detail = fmt::format(
        "max |error| {:.3g} over {} nodes (tolerance {:.3g}; reference's max error {:.2g}; table's own max standard "
        "error {:.3g})",
        max_err, nodes.size(), tol, max_ref_err, max_se);
    // A pass needs a reference good to the tolerance (else a table error beyond it could pass).
    const Status st = ok && max_ref_err > tol
                          ? verdicts.not_judged(check, label, kNoView, detail,
                                                "the reference's own error exceeds the tolerance at some sample")
                          : verdicts.add(check, ok, label, kNoView, detail);
    json j = {{"name", info.name}, {"layout", renderer ? "renderer" : "published"}, {"label", label},
              {"stores", info.stores}, {"reference", info.glass ? "generator quadrature (lutgen/microfacet_quadrature.h), 1e-6"
                                                                : "independent quadrature over h (validate/lut_reference.h)"},
              {"axes", axes}, {"cells", jc}, {"nodes", nodes.size()}, {"max_abs_error", max_err},
              {"max_table_se", max_se}, {"max_reference_err", max_ref_err}, {"tolerance", tol}, {"passed", ok},
              {"verdict", status_word(st)}};
    if (!values.is_null()) j["values"] = values;
    arr.push_back(j);
  }
  return {{"available", true}, {"layout", renderer ? "renderer" : "published"}, {"tolerance", s.lut_tol},
          {"renderer_tolerance", s.renderer_lut_tol},
          {"renderer_average_tolerance", s.renderer_avg_lut_tol}, {"panels", s.lut_quadrature.panels}, {"tables", arr}};
}

// ---------------------------------------------------------------- pictures

json run_images(const Catalog& cat, const SuiteSettings& s, const std::string& dir) {
  json arr = json::array();
  std::size_t total = 0;
  for (const FurnaceRow& r : cat.furnace_rows) total += r.bsdfs.size();
  Progress progress("furnace spheres", total, s.progress && Progress::stderr_is_terminal());
  uint64_t stream = 0;
  for (const FurnaceRow& row : cat.furnace_rows) {
    std::vector<RgbImage> imgs;
    json lum = json::array();
    for (const auto& b : row.bsdfs) {
      imgs.push_back(furnace_sphere(*b, s.image_res, s.image_spp, s.seed, ++stream));
      std::vector<float> y(std::size_t(s.image_res) * s.image_res);
      for (int py = 0; py < s.image_res; ++py)
        for (int px = 0; px < s.image_res; ++px) y[std::size_t(py) * s.image_res + px] = imgs.back().at(px, py)[1];
      lum.push_back(y);
      progress.add();
    }
    const RgbImage strip = hconcat(imgs, 2);
    std::string base;
    for (char ch : row.name) base += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    write_rgb_image(dir + "/images/furnace_" + base + ".exr", strip);
    write_rgb_image(dir + "/images/furnace_" + base + ".png", strip);
    arr.push_back({{"name", row.name}, {"parameter", row.parameter}, {"values", row.values}, {"note", row.note},
                   {"exr", "images/furnace_" + base + ".exr"}, {"png", "images/furnace_" + base + ".png"},
                   {"res", s.image_res}, {"spp", s.image_spp}, {"albedo_green", lum}});
  }
  progress.finish();
  return arr;
}

// ---------------------------------------------------------------- convergence

json run_convergence(const Catalog& cat, const SuiteSettings& s) {
  json arr = json::array();
  if (s.convergence_samples.empty()) return arr;
  // Cases: every case of the chosen components (a row of roughness values), except those without
  // a non-delta part (roughness 0 of a single specular lobe: both estimators are exactly 0 there).
  const int repeats = 8;
  const Vec3 v = view_dir(0.5);
  std::vector<std::size_t> cases;
  for (std::size_t c = 0; c < cat.cases.size(); ++c) {
    const auto& comps = s.convergence_components;
    if (std::find(comps.begin(), comps.end(), cat.cases[c].component) != comps.end()) cases.push_back(c);
  }
  const std::size_t nmax = s.convergence_samples.back(), nn = s.convergence_samples.size();
  // Reference per case: sampled estimator (non-delta part, the integral both estimators share) with
  // 16x the largest budget. Then both estimators per (case, budget, repeat). Each with its own
  // random stream; all of them in one parallel loop (the references first: the largest items).
  std::vector<AlbedoEstimate> refs(cases.size());
  std::vector<double> de(cases.size() * nn * repeats), ds(de.size());
  tbb::parallel_for(std::size_t(0), refs.size() + de.size(), [&](std::size_t item) {
    if (item < refs.size()) {
      refs[item] = albedo_sampled(*cat.cases[cases[item]].bsdf, v, 16 * nmax, s.seed, 900000 + cases[item]).non_delta;
      return;
    }
    const std::size_t idx = item - refs.size(), k = idx / (nn * repeats), ni = (idx / repeats) % nn;
    const int r = int(idx % repeats);
    const std::size_t c = cases[k], n = s.convergence_samples[ni];
    const Bsdf& b = *cat.cases[c].bsdf;
    const int strata = std::max(1, int(std::lround(std::sqrt(n / 2.0))));
    de[idx] = albedo_eval(b, v, strata, s.seed + 17 + r, 800000 + c).value.g;
    ds[idx] = albedo_sampled(b, v, n, s.seed + 17 + r, 700000 + c).non_delta.value.g;
  });
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const double ref = refs[k].value.g;
    if (ref < 1e-3) continue;
    json ns = json::array(), e_eval = json::array(), e_samp = json::array();
    for (std::size_t ni = 0; ni < nn; ++ni) {
      double se = 0, ss = 0;
      for (int r = 0; r < repeats; ++r) {  // fixed order
        const std::size_t idx = (k * nn + ni) * repeats + r;
        const double e = de[idx] - ref, d = ds[idx] - ref;
        se += e * e;
        ss += d * d;
      }
      ns.push_back(s.convergence_samples[ni]);
      e_eval.push_back(std::sqrt(se / repeats));
      e_samp.push_back(std::sqrt(ss / repeats));
    }
    const BsdfCase& bc = cat.cases[cases[k]];
    arr.push_back({{"case", bc.name}, {"component", bc.component}, {"cos", 0.5},
                   {"reference", ref}, {"reference_se", refs[k].std_error.g}, {"repeats", repeats},
                   {"samples", ns}, {"rms_error_eval", e_eval}, {"rms_error_sampled", e_samp}});
  }
  return arr;
}

}  // namespace

const char* status_word(Status s) {
  switch (s) {
    case Status::Fail: return "FAIL";
    case Status::NotJudged: return "NOT JUDGED";
    case Status::Waived: return "WAIVED";
    default: return "PASS";
  }
}

std::string banner(const json& rep) {
  int failed = 0, waived = 0, not_judged = 0, total = 0;
  std::vector<std::string> unjudged;
  for (const json& c : rep.at("summary")) {
    failed += c.at("failed").get<int>();
    waived += c.at("waived").get<int>();
    total += c.at("total").get<int>();
    const int nj = c.at("not_judged").get<int>();
    not_judged += nj;
    if (nj > 0) unjudged.push_back(fmt::format("{} ({} of {})", c.at("check").get<std::string>(), nj, c.at("total").get<int>()));
  }
  const std::string verdict =
      failed > 0 ? fmt::format("FAIL: {} verdict(s) failed", failed)
                 : fmt::format("PASS: no unwaived failure{}", waived > 0 ? fmt::format(" ({} waived)", waived) : "");
  const std::string nj = fmt::format("{} of {} verdicts NOT JUDGED (the check could not have failed there)", not_judged, total);
  if (rep.at("mode") != "quick") return fmt::format("FULL run. {}; {}.", verdict, nj);
  const json& e = rep.at("energy");
  return fmt::format(
      "QUICK run, not the full validation. {}; {}. It cannot judge: {}; nor the cases, view directions and table "
      "cells only the full run has (white furnace at cos {} with {} samples; dspbr validate --out DIR for the full "
      "run).",
      verdict, nj, unjudged.empty() ? std::string("-") : fmt::format("{}", fmt::join(unjudged, "; ")),
      fmt::join(e.at("cos").get<std::vector<double>>(), ", "), e.at("samples").get<std::size_t>());
}

std::vector<std::string> missing_tables(const LutSet& l) {
  std::vector<std::string> out;
  for (const LutInfo& info : lut_registry()) {
    if (!info.dspbr || (info.layouts & kPublishedLayout) == 0) continue;  // DSPBR 2025x's six
    const Table& t = l.published_table(info.id);
    if (t.values.empty() || t.axes.empty()) out.push_back(info.name);
  }
  return out;
}

SuiteSettings SuiteSettings::defaults(bool quick) {
  SuiteSettings s;
  s.quick = quick;
  if (quick) {
    s.furnace_cos = {1.0, 0.5, 0.1, 0.02};  // 0.02: grazing view (table artefacts show there)
    // The quadrature judges the bounds; the sampled estimator mainly the agreement (band <= 0.02),
    // growing where it needs more (measured: 22 of 128 quick rows do, 6 of them to the cap).
    s.furnace_quadrature_tolerance = 1e-4;
    s.furnace_samples = 16384;
    s.furnace_samples_max = 262144;
    s.reciprocity_pairs = 2000;
    s.chi2.samples = 50000;
    s.chi2.theta_bins = 20;
    s.chi2.max_depth = 3;
    s.chi2_cos = {0.6};
    s.chi2_cos_below = {-0.6};
    s.stability.random_directions = 200;
    s.lut_cells_per_axis = 3;  // ends and middle: the roughness-0 samples (limits) are not checked
    s.lut_quadrature.panels = 12;
    s.image_res = 24;
    s.image_spp = 16;
    s.convergence_samples = {16, 64, 256, 1024};
    s.convergence_components = {"metallic"};
  } else {
    s.furnace_cos = {1.0, 0.8, 0.5, 0.3, 0.1, 0.02};
    s.furnace_quadrature_tolerance = 1e-4;
    s.furnace_samples = 65536;
    s.furnace_samples_max = 4194304;
    s.reciprocity_pairs = 20000;
    s.chi2.samples = 1000000;
    s.chi2.theta_bins = 64;
    s.chi2.consistency_stride = 8;
    s.chi2_cos = {0.5, 0.05};
    s.chi2_cos_below = {-0.3};  // from inside, beyond the critical angle of eta 1.5 (TIR)
    s.stability.random_directions = 300;
    s.lut_cells_per_axis = 5;
    // 48 panels: at 24 the reference of GGX_E at r = 0.26, cos 0.0046 was off by 3e-4 (its
    // half-panel error estimate 2e-4), more than the renderer tables' tolerance.
    s.lut_quadrature.panels = 48;
    s.image_res = 64;
    s.image_spp = 256;
    s.convergence_samples = {16, 64, 256, 1024, 4096, 16384, 65536};
    s.convergence_components = {"metallic", "opaque_dielectric"};
  }
  return s;
}

// UTC date and time of now, ISO 8601.
std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

namespace {

json cases_json(const Catalog& cat) {
  json cases = json::array();
  for (const BsdfCase& c : cat.cases)
    cases.push_back({{"case", c.name}, {"component", c.component}, {"params", c.params}, {"claim", claim_name(c.claim)},
                     {"note", c.note}});
  return cases;
}

// The conformance verdicts of another implementation: one per group of the vector set.
json run_other_conformance(const OtherImplementation& other, Verdicts& verdicts) {
  json groups = json::array();
  std::size_t vectors = 0, failed = 0;
  for (const ConformanceGroup& g : other.conformance()) {
    const Status st = verdicts.add("conformance: vectors within tolerance", g.failed == 0, g.group, kNoView,
                                   fmt::format("{} of {} vectors fail (worst error / tolerance {:.3g}, {})", g.failed,
                                               g.vectors, g.worst_ratio, g.worst_id));
    groups.push_back({{"group", g.group}, {"vectors", g.vectors}, {"failed", g.failed}, {"worst_ratio", g.worst_ratio},
                      {"worst_id", g.worst_id}, {"verdict", status_word(st)}});
    vectors += g.vectors;
    failed += g.failed;
  }
  return {{"vector_set", other.vector_set}, {"vectors", vectors}, {"failed", failed}, {"groups", groups}};
}

}  // namespace

SuiteResult run_suite(const Catalog& cat, const LutSet* luts, const SuiteSettings& s, const std::string& dir,
                      const OtherImplementation* other) {
  Verdicts verdicts;
  verdicts.luts = cat.luts ? cat.luts : luts;  // waivers of table effects follow the BSDF's tables
  json report;
  report["tool"] = "dspbr validate";
  report["mode"] = s.quick ? "quick" : "full";
  report["seed"] = s.seed;
  // Provenance that the numbers depend on (stays in the bit-identical part of the report) ...
  report["provenance"] = {{"project_version", project_version()}, {"git_commit", git_describe()},
                          {"seed", s.seed}, {"mode", s.quick ? "quick" : "full"}, {"tables", s.table_file}};
  // ... and what they do not depend on: the only part that differs between runs of the same seed.
  report["run"] = {{"date_utc", utc_now()}, {"threads", tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)},
                   {"command_line", s.command_line}};
  report["skipped"] = cat.skipped;
  report["cases"] = cases_json(cat);
  // Wall-clock time per phase: reported on stderr only (the report stays bit-identical).
  auto timed = [&](const char* name, auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();  // processor time of all threads
    json r = f();
    if (s.progress)
      print_phase_time(name, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                       double(std::clock() - c0) / CLOCKS_PER_SEC);
    return r;
  };
  report["energy"] = timed("energy", [&] { return run_energy(cat, s, verdicts); });
  report["reciprocity"] = timed("reciprocity", [&] { return run_reciprocity(cat, s, verdicts); });
  report["chi2"] = timed("chi2", [&] { return run_chi2(cat, s, verdicts); });
  report["stability"] = timed("stability", [&] { return run_stability(cat, s, verdicts); });
  report["tables"] = timed("tables", [&] { return run_luts(luts, s, verdicts); });
  if (!luts) report["skipped"].push_back("tables: no LUT file (luts/dspbr_luts.json) could be loaded");
  report["furnace_images"] = timed("furnace_images", [&] { return run_images(cat, s, dir); });
  report["convergence"] = timed("convergence", [&] { return run_convergence(cat, s); });
  if (other) {
    // The same checks with the same settings (the chi-square's consistency within the other's
    // rounding; no histograms), its verdicts named apart.
    SuiteSettings so = s;
    so.chi2.consistency_tol = std::max(s.chi2.consistency_tol, other->consistency_tol);
    if (other->chi2_samples_max > 0) so.chi2.samples = std::min(so.chi2.samples, other->chi2_samples_max);
    so.chi2_histograms = 0;
    verdicts.prefix = "shader library: ";
    json lib = {{"name", other->name}, {"cases", cases_json(other->catalog)}, {"left_out", other->left_out},
                {"consistency_tol", so.chi2.consistency_tol}};
    lib["energy"] = timed("lib energy", [&] { return run_energy(other->catalog, so, verdicts); });
    lib["chi2"] = timed("lib chi2", [&] { return run_chi2(other->catalog, so, verdicts); });
    lib["stability"] = timed("lib stability", [&] { return run_stability(other->catalog, so, verdicts); });
    lib["conformance"] = timed("lib conformance", [&] { return run_other_conformance(*other, verdicts); });
    report["shader_library"] = lib;
    verdicts.prefix.clear();
  }
  // The table integrators' trade (docs/design/luts.md, "Speed"): the committed study, plotted by the report.
  report["integrator_study"] = {{"source", "luts/integrator_study.csv (dspbr lut --bench-integrators)"},
                                {"csv", std::string(committed_integrator_study_csv())}};
  json summary = json::array();
  int failed = 0;
  for (const auto& [name, c] : verdicts.counts) {
    summary.push_back({{"check", name}, {"passed", c.passed}, {"failed", c.failed}, {"waived", c.waived},
                       {"not_judged", c.not_judged}, {"total", c.passed + c.failed + c.waived + c.not_judged}});
    failed += c.failed;
  }
  report["summary"] = summary;
  report["banner"] = banner(report);
  report["failures"] = verdicts.failures;
  report["verdicts_not_passed"] = verdicts.listed;
  json waivers = json::array();
  for (std::size_t k = 0; k < dspbr_waivers().size(); ++k) {
    const Waiver& w = dspbr_waivers()[k];
    waivers.push_back({{"id", w.id}, {"check", w.check}, {"cases", w.cases},
                       {"below_first_cell_of", w.below_first_cell_of}, {"reason", w.reason}, {"spec", w.spec},
                       {"used", verdicts.waiver_uses[k]}});
  }
  report["waivers"] = waivers;
  write_text_atomically(dir + "/data/report.json", json_text(report, 1, "validation report"));
  SuiteResult r;
  r.failed_checks = failed;
  r.failures = verdicts.failures;
  r.waived = verdicts.waived;
  r.report = std::move(report);
  return r;
}

void print_phase_time(const char* name, double wall_s, double cpu_s) {
  std::fprintf(stderr, "  %-16s %6.1fs  (cpu %6.1fs)\n", name, wall_s, cpu_s);
}

}  // namespace dspbr::validate
