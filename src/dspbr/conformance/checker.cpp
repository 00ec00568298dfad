#include "dspbr/conformance/checker.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>

#include "dspbr/conformance/vector_file.h"
#include "dspbr/io/message.h"

namespace dspbr::conformance {

double rgb_ratio(const Tolerance& t, const Rgb& got, const Rgb& expected) {
  return std::max({t.ratio(got.r, expected.r), t.ratio(got.g, expected.g), t.ratio(got.b, expected.b)});
}

namespace {

using OJson = nlohmann::ordered_json;

// Directions of delta lobes match within this distance (unit vectors).
constexpr double kDeltaDirection = 1e-6;

// Every expected delta lobe against the sum of the supplied lobes towards its direction (none
// counts as 0: an implementation may split one direction's energy, never repeat it); the
// supplied lobes towards no expected direction are judged, summed per direction, against 0.
double delta_ratio(const Tolerance& t, const std::vector<DeltaExpectation>& got, const std::vector<DeltaExpectation>& expected) {
  double worst = 0;
  std::vector<bool> used(got.size(), false);
  for (const DeltaExpectation& e : expected) {
    Rgb value{0, 0, 0};
    for (std::size_t i = 0; i < got.size(); ++i)
      if (!used[i] && length(got[i].l - e.l) < kDeltaDirection) value += got[i].value, used[i] = true;
    worst = std::max(worst, rgb_ratio(t, value, e.value));
  }
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (used[i]) continue;
    Rgb value = got[i].value;
    for (std::size_t k = i + 1; k < got.size(); ++k)
      if (!used[k] && length(got[k].l - got[i].l) < kDeltaDirection) value += got[k].value, used[k] = true;
    worst = std::max(worst, rgb_ratio(t, value, Rgb{0, 0, 0}));
  }
  return worst;
}

OJson counts_json(std::size_t judged, std::size_t passed, std::size_t not_judged, std::size_t ignored) {
  return OJson{{"judged", judged}, {"passed", passed}, {"failed", judged - passed}, {"not_judged", not_judged},
               {"ignored", ignored}};
}

bool negative(const Rgb& c) { return c.r < 0 || c.g < 0 || c.b < 0; }

OJson ratio_json(const std::optional<double>& r) { return r ? OJson(std::min(*r, 1e300)) : OJson(nullptr); }

}  // namespace

const char* quantity_name(Quantity q) {
  switch (q) {
    case Quantity::FCos: return "f_cos";
    case Quantity::Pdf: return "pdf";
    case Quantity::Albedo: return "albedo";
    case Quantity::Emission: return "emission";
    case Quantity::Delta: return "delta";
  }
  return "?";
}

Check check_results(const std::vector<Vector>& vectors, const std::vector<Result>& results) {
  Check c;
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    const Vector& v = vectors[i];
    const Result& r = results[i];
    VectorVerdict x;
    if (r.f_cos) x.ratio[int(Quantity::FCos)] = rgb_ratio(v.tolerance, *r.f_cos, v.f_cos);
    if (r.pdf) x.ratio[int(Quantity::Pdf)] = v.pdf_tolerance.ratio(*r.pdf, v.pdf);
    if (r.albedo && v.albedo) x.ratio[int(Quantity::Albedo)] = rgb_ratio(v.albedo_tolerance, *r.albedo, *v.albedo);
    if (r.emission && v.emission)
      x.ratio[int(Quantity::Emission)] = rgb_ratio(v.emission_tolerance, *r.emission, *v.emission);
    if (r.delta) x.ratio[int(Quantity::Delta)] = delta_ratio(v.delta_tolerance, *r.delta, v.delta);
    // A negative value is never legal (f cos, pdf, albedo, emission, a delta lobe): it fails
    // whatever its tolerance, with the ratio of a non-finite value (kNegativeRatio).
    bool below_zero[kQuantities] = {r.f_cos && negative(*r.f_cos), r.pdf && *r.pdf < 0, r.albedo && negative(*r.albedo),
                                    r.emission && negative(*r.emission), false};
    if (r.delta)
      for (const DeltaExpectation& d : *r.delta) below_zero[int(Quantity::Delta)] |= negative(d.value);
    for (int q = 0; q < kQuantities; ++q)
      if (x.ratio[q] && below_zero[q]) x.ratio[q] = kNegativeRatio;
    for (const auto& q : x.ratio)
      if (q) x.worst_ratio = std::max(x.worst_ratio, *q), x.supplied = true;
    x.passed = x.supplied && x.worst_ratio <= 1;
    c.failed += x.supplied && !x.passed ? 1 : 0;
    c.not_supplied += x.supplied ? 0 : 1;
    c.verdicts.push_back(x);
  }
  return c;
}

OJson check_report(const std::vector<Vector>& vectors, const std::vector<Result>& results, const Check& check,
                   const OJson& provenance, std::size_t worst) {
  OJson rep;
  rep["format"] = "dspbr-conformance-report";
  rep["version"] = kFormatVersion;
  rep["provenance"] = provenance;
  rep["verdict"] = check.passed() ? "PASS" : "FAIL";
  rep["summary"] = {{"vectors", vectors.size()},
                    {"passed", check.judged() - check.failed},
                    {"failed", check.failed},
                    {"not_supplied", check.not_supplied}};

  // Per quantity: judged where both the vector has the expectation and the results supply it; not
  // judged where a vector with a result lacks it.
  OJson quantities = OJson::object();
  for (int q = 0; q < kQuantities; ++q) {
    // Ignored: supplied for a vector without that expectation (an albedo where the set has none).
    std::size_t judged = 0, passed = 0, not_judged = 0, ignored = 0;
    for (std::size_t i = 0; i < vectors.size(); ++i) {
      const auto& r = check.verdicts[i].ratio[q];
      const Vector& v = vectors[i];
      const Result& res = results[i];
      if (r) ++judged, passed += *r <= 1 ? 1 : 0;
      else if ((q == int(Quantity::Albedo) && res.albedo) || (q == int(Quantity::Emission) && res.emission)) ++ignored;
      else if (check.verdicts[i].supplied) {  // (a vector not supplied at all is counted as such)
        const bool expected = q == int(Quantity::FCos) || q == int(Quantity::Pdf) ||
                              (q == int(Quantity::Albedo) && v.albedo) || (q == int(Quantity::Emission) && v.emission) ||
                              (q == int(Quantity::Delta) && !v.delta.empty());
        not_judged += expected ? 1 : 0;
      }
    }
    quantities[quantity_name(Quantity(q))] = counts_json(judged, passed, not_judged, ignored);
  }
  rep["quantities"] = quantities;

  // Per group (in order of first appearance) and per active component (in bit order of first appearance).
  auto tally = [&](const std::function<std::vector<std::string>(const Vector&)>& keys) {
    std::vector<std::string> order;
    std::map<std::string, OJson> acc;
    for (std::size_t i = 0; i < vectors.size(); ++i) {
      const VectorVerdict& x = check.verdicts[i];
      for (const std::string& k : keys(vectors[i])) {
        auto it = acc.find(k);
        if (it == acc.end()) {
          order.push_back(k);
          it = acc.emplace(k, OJson{{"name", k}, {"verdict", "NOT SUPPLIED"}, {"vectors", 0}, {"passed", 0}, {"failed", 0},
                                    {"not_supplied", 0}, {"worst_ratio", 0.0}, {"worst_id", vectors[i].id}}).first;
        }
        OJson& g = it->second;
        g["vectors"] = g["vectors"].get<int>() + 1;
        const char* count = !x.supplied ? "not_supplied" : (x.passed ? "passed" : "failed");
        g[count] = g[count].get<int>() + 1;
        // FAIL when one fails; PASS when one passes and none fails; else NOT SUPPLIED.
        if (x.supplied && !x.passed) g["verdict"] = "FAIL";
        else if (x.passed && g["verdict"] == "NOT SUPPLIED") g["verdict"] = "PASS";
        if (x.worst_ratio > g["worst_ratio"].get<double>()) {
          g["worst_ratio"] = std::min(x.worst_ratio, 1e300);
          g["worst_id"] = vectors[i].id;
        }
      }
    }
    OJson out = OJson::array();
    for (const std::string& k : order) out.push_back(acc[k]);
    return out;
  };
  rep["groups"] = tally([](const Vector& v) { return std::vector<std::string>{v.group}; });
  rep["components"] = tally([](const Vector& v) { return v.components; });

  // The worst vectors, with what an implementer needs to reproduce them.
  std::vector<std::size_t> order(vectors.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return check.verdicts[a].worst_ratio > check.verdicts[b].worst_ratio;
  });
  OJson worst_list = OJson::array();
  for (std::size_t k = 0; k < order.size() && worst_list.size() < worst; ++k) {
    const std::size_t i = order[k];
    if (!check.verdicts[i].supplied) continue;
    OJson w = vector_json(vectors[i]);
    OJson got = OJson::object();
    if (results[i].f_cos) got["f_cos"] = {results[i].f_cos->r, results[i].f_cos->g, results[i].f_cos->b};
    if (results[i].pdf) got["pdf"] = *results[i].pdf;
    if (results[i].albedo) got["albedo"] = {results[i].albedo->r, results[i].albedo->g, results[i].albedo->b};
    if (results[i].emission) got["emission"] = {results[i].emission->r, results[i].emission->g, results[i].emission->b};
    w["result"] = got;
    w["verdict"] = check.verdicts[i].verdict();
    w["worst_ratio"] = std::min(check.verdicts[i].worst_ratio, 1e300);
    worst_list.push_back(w);
  }
  rep["worst"] = worst_list;

  // Every vector: verdict and ratios (null: NOT JUDGED), and the relative error of f cos (the plots).
  OJson all = OJson::array();
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    const VectorVerdict& x = check.verdicts[i];
    const Vector& v = vectors[i];
    OJson error = nullptr;  // f cos not supplied
    if (const auto& got = results[i].f_cos) {
      double rel = 0;
      for (auto [g, e] : {std::pair{got->r, v.f_cos.r}, {got->g, v.f_cos.g}, {got->b, v.f_cos.b}})
        rel = std::max(rel, std::abs(g - e) / std::max(std::abs(e), v.tolerance.abs));
      error = std::min(rel, 1e300);
    }
    OJson j{{"id", v.id}, {"group", v.group}, {"verdict", x.verdict()}, {"f_cos_error", error}};
    for (int q = 0; q < kQuantities; ++q) j[std::string(quantity_name(Quantity(q))) + "_ratio"] = ratio_json(x.ratio[q]);
    all.push_back(j);
  }
  rep["vectors"] = all;
  return rep;
}

void select_vectors(const Selection& s, std::vector<Vector>& vectors, std::vector<Result>& results) {
  // Every name asked for must be one of the set's, else a misspelling would silently judge nothing.
  const auto check_names = [&](const std::vector<std::string>& asked, const char* option, auto names_of) {
    std::set<std::string> known;
    for (const Vector& v : vectors)
      for (const std::string& n : names_of(v)) known.insert(n);
    for (const std::string& a : asked)
      if (!known.count(a)) {
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        throw std::invalid_argument(std::string(option) + ": no vector has " + in_quotes(a) + " (the set has: " + list + ")");
      }
  };
  check_names(s.groups, "--groups", [](const Vector& v) { return std::vector<std::string>{v.group}; });
  check_names(s.components, "--components", [](const Vector& v) { return v.components; });
  const auto has = [](const std::vector<std::string>& list, const std::string& x) {
    return std::find(list.begin(), list.end(), x) != list.end();
  };
  std::vector<Vector> kept_vectors;
  std::vector<Result> kept_results;
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    bool keep = s.groups.empty() || has(s.groups, vectors[i].group);
    if (keep && !s.components.empty())
      keep = std::any_of(vectors[i].components.begin(), vectors[i].components.end(),
                         [&](const std::string& c) { return has(s.components, c); });
    if (!keep) continue;
    kept_vectors.push_back(std::move(vectors[i]));
    kept_results.push_back(std::move(results[i]));
  }
  // Each name exists but no vector has both (a group whose materials lack the component): the
  // options, not the results, leave nothing to judge.
  if (kept_vectors.empty() && !s.groups.empty() && !s.components.empty())
    throw std::invalid_argument("--groups and --components: no vector is in one of the groups and has one of the components");
  vectors = std::move(kept_vectors);
  results = std::move(kept_results);
}

}  // namespace dspbr::conformance
