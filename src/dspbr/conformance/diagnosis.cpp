#include "dspbr/conformance/diagnosis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <tbb/parallel_for.h>

#include "dspbr/bsdf/sheen_lobe.h"
#include "dspbr/component.h"
#include "dspbr/fresnel.h"
#include "dspbr/ggx.h"
#include "dspbr/sheen.h"

namespace dspbr::conformance {

namespace {

using OJson = nlohmann::ordered_json;

Cause deviation(const char* name, const char* term, const char* evidence, const char* remedy, Deviation d) {
  Cause c{name, term, evidence, remedy};
  c.deviation = d;
  return c;
}
Cause tables(const char* name, const char* term, const char* evidence, const char* remedy, DemoTables t) {
  Cause c{name, term, evidence, remedy};
  c.tables = t;
  return c;
}

// The clamp of the roughness_clamp cause: a common one (alpha = 4e-6, a lobe narrow enough to look
// like a mirror in a render, not in f at the peak).
constexpr double kClampedRoughness = 0.002;

bool negative(const Rgb& c) { return c.r < 0 || c.g < 0 || c.b < 0; }

// What one vector says for the diagnosis: which of f cos and emission it judged, and whether they
// failed. Other quantities (pdf, albedo, delta lobes) are not diagnosed.
struct Judged {
  bool f_cos = false, emission = false;
  bool failing = false, passing = false;
};

Judged judged(const Vector& x, const Result& r, const VectorVerdict& v) {
  Judged j;
  const auto& rf = v.ratio[int(Quantity::FCos)];
  const auto& re = v.ratio[int(Quantity::Emission)];
  j.f_cos = rf.has_value() && !negative(*r.f_cos);
  j.emission = re.has_value() && x.emission && !negative(*r.emission);
  if (!j.f_cos && !j.emission) return j;
  j.failing = (j.f_cos && *rf > 1) || (j.emission && *re > 1);
  j.passing = !j.failing;
  return j;
}

// The reference made as `base` says plus the cause (m: the vector's material, built once per vector).
MaterialBsdf cause_bsdf(const Vector& x, const Material& m, const Cause& c, const Representation& base) {
  Representation r = base;
  if (c.tables != DemoTables::Renderer) r.tables = &demo_table_set(c.tables);
  r.min_roughness = std::max(base.min_roughness, c.min_roughness);
  return represented_bsdf(x, m, r, c.deviation);
}

OJson rgb_json(const Rgb& c) { return OJson::array({c.r, c.g, c.b}); }

// Whether the results agree with the reference made with the cause (within the vector's tolerances).
bool agrees(const Vector& x, const Material& m, const Result& r, const Judged& j, const Cause& c,
            const Representation& base) {
  const MaterialBsdf b = cause_bsdf(x, m, c, base);
  if (j.f_cos && rgb_ratio(x.tolerance, *r.f_cos, b.eval(x.v, x.l) * std::abs(x.l.z)) > 1) return false;
  if (j.emission && rgb_ratio(x.emission_tolerance, *r.emission, b.emission(x.v)) > 1) return false;
  return true;
}

// A cause that is the representation already judged against cannot explain anything.
bool applies(const Cause& c, const Representation& base) {
  if (c.tables != DemoTables::Renderer && base.tables == &demo_table_set(c.tables)) return false;
  if (c.min_roughness > 0 && base.min_roughness >= c.min_roughness) return false;
  return true;
}

void rank(Ranking& r, const std::vector<CauseScore>& scores) {
  // A cause that passing vectors contradict as often as failing ones confirm it is a coincidence
  // (the eighth fresh tester's pass: all-zero results were "explained" by a transmission Fresnel).
  for (const CauseScore& s : scores)
    if (s.explains > s.contradicts) r.causes.push_back(s);
  // Explained minus contradicted, then explained, then the vocabulary's order (stable).
  std::stable_sort(r.causes.begin(), r.causes.end(), [](const CauseScore& a, const CauseScore& b) {
    const long da = long(a.explains) - long(a.contradicts), db = long(b.explains) - long(b.contradicts);
    return da != db ? da > db : a.explains > b.explains;
  });
}

}  // namespace

const std::vector<Cause>& causes() {
  static const std::vector<Cause> list = [] {
    std::vector<Cause> c;
    c.push_back(deviation(
        "multiple_scattering", "M_r,ms F_ms, the multiple-scattering lobe (spec \"Energy Preservation\")",
        "rough specular lobes too dark by F_ms (1 - E(mu_v)) (1 - E(mu_l)) / (pi (1 - E_avg)): growing with "
        "roughness, nothing at roughness 0.1 or below",
        "add the M_r,ms F_ms lobe, with E_m and E_m,avg from the tables (docs/bsdf.md)", Deviation::NoMultipleScattering));
    c.push_back(deviation(
        "fms_of_mix", "F_ms of the core's mixed Fresnel (spec \"Putting It All Together\")",
        "only where 0 < metallic < 1 and rough: F_ms blended from the metal's and the dielectric's is not F_ms "
        "of the blended F_0 and F_90 (F_ms is not linear in them)",
        "compute F_ms once from rho_s,r,0 = (1 - m) s F_0 rho_s + m rho and rho_s,r,90 = (1 - m) s + m",
        Deviation::BlendedFms));
    c.push_back(deviation(
        "bc_f0", "B_c, the diffuse base's coupling to the specular albedo (spec \"Energy Preservation\")",
        "only in the diffuse base where s < 1 or metallic > 0: E and E_avg read at max(rho_s,r,0) instead of "
        "max(F_0 rho_s)",
        "read E(mu; r, f0) and E_avg(r, f0) at f0 = max(F_0 rho_s)", Deviation::BcMaxRhoSr0));
    c.push_back(deviation(
        "sheen_layering", "ShinyCore's albedo scaling min(1 - rho_b E_b(mu_v), 1 - rho_b E_b(mu_l)) (spec \"Sheen\")",
        "only under a sheen, and everything below it: too bright by the sheen's albedo max(rho_b) E_b",
        "scale the core by the sheen's albedo scaling, E_b from the Sheen_E / Sheen_ash_E tables",
        Deviation::NoSheenLayering));
    c.push_back(deviation(
        "sheen_lambda", "the sheen's Smith Lambda fit (spec Tables sheen-lambda-fit and -w)",
        "only in the sheen lobe with the spec's visibility, most at grazing angles: Conty & Kulla 2017's Lambda "
        "fit and blend instead of the spec's",
        "use the spec's coefficients and blend w(alpha_b) (docs/sheen_lambda.md)", Deviation::OldSheenLambda));
    c.push_back(deviation(
        "transmission_fresnel", "the rough volumetric transmission's 1 - s F(v.h) (spec \"Microfacet BSDF\")",
        "only in rough transmission through a volume's boundary, growing with roughness and with the angle "
        "between v and the normal: the Fresnel read at the macro normal (v.n)",
        "evaluate the Fresnel at the refraction's microfacet normal h", Deviation::FresnelAtMacroNormal));
    c.push_back(deviation(
        "grazing_lambda", "the GGX Smith Lambda near the horizon (spec \"Microfacet BSDF\")",
        "only where cos theta_v or cos theta_l is tiny (1e-4 in the extremes), off by a factor ~1/cos theta: "
        "Lambda set to 0 below a cosine (a guard) lets f grow like 1/cos",
        "evaluate Lambda down to the horizon in a form without cancellation, x / (2 (1 + sqrt(1 + x))), "
        "x = alpha^2 tan^2 theta",
        Deviation::LambdaZeroAtGrazing));
    c.push_back(deviation(
        "emission_coat", "the emission's clearcoat attenuation 1 - c F_c(v.n_c) (spec \"Emission\")",
        "only the emission of coated materials, too bright by c F_c(v.n_c)",
        "multiply the emission by 1 - c F_c(v.n_c)", Deviation::EmissionUnattenuated));
    Cause clamp{"roughness_clamp", "roughness 0 as Dirac lobes (docs/bsdf.md, \"Conventions\")",
                "only at mirror directions of roughness-0 materials: a narrow lobe (roughness clamped to 0.002) "
                "where the vectors have a Dirac lobe, f cos at the peak ~1e5 over the tolerance",
                "treat roughness 0 as Dirac lobes, or judge with --min-roughness R (your clamp: the mirrors then "
                "count by their reflectance)"};
    clamp.min_roughness = kClampedRoughness;
    c.push_back(clamp);
    c.push_back(tables(
        "albedo_approximation", "the albedo tables E_m and E_m,avg (spec \"Energy Preservation\")",
        "wherever the compensation reads the albedo (rough lobes, the diffuse base): an analytic approximation "
        "(Karis 2014, 1 - 0.55 r) instead of the GGX_E tables",
        "read the tables (luts/dspbr_lookup.*) or the fits (fits/), or judge with --tables analytic",
        DemoTables::Analytic));
    c.push_back(tables("published_tables", "the energy tables' values at the point of use (docs/luts.md)",
                       "small errors wherever a table is read, largest at grazing angles and low roughness: the "
                       "published tables with multilinear lookups",
                       "read the renderer-layout tables (luts/), or judge with --tables published",
                       DemoTables::Published));
    c.push_back(tables("fits", "the energy tables' values at the point of use (docs/fits.md)",
                       "small errors where a table is read: the LUT-free fits", "judge with --tables fits",
                       DemoTables::Fits));
    return c;
  }();
  return list;
}

Diagnosis diagnose(const std::vector<Vector>& vectors, const std::vector<Result>& results, const Check& check,
                   const Representation& base) {
  if (results.size() != vectors.size() || check.verdicts.size() != vectors.size())
    throw std::logic_error("diagnose: results and verdicts must match the vectors");
  const std::vector<Cause>& vocabulary = causes();
  const std::size_t n = vectors.size(), nc = vocabulary.size();
  std::vector<Judged> j(n);
  for (std::size_t i = 0; i < n; ++i) j[i] = judged(vectors[i], results[i], check.verdicts[i]);
  // A vector whose expectations the reference (as `base`) does not reproduce, from an edited or
  // stale vector file, says nothing about causes: left out and counted (the eighth fresh tester's
  // pass: every cause "explained" glass vectors whose ior had been edited).
  // agree[i * nc + c]: vector i agrees with cause c (only for vectors judged on f cos or emission).
  std::vector<char> unreproduced(n, 0), agree(n * nc, 0);
  const Cause none{"", "", "", ""};
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    if (!j[i].failing && !j[i].passing) return;
    const Vector& x = vectors[i];
    const Material m = vector_material(x);
    Result expected;
    expected.f_cos = x.f_cos;
    if (x.emission) expected.emission = *x.emission;
    Judged all = j[i];
    all.f_cos = true, all.emission = x.emission.has_value();
    if (!agrees(x, m, expected, all, none, base)) {
      unreproduced[i] = 1;
      j[i] = Judged{};
      return;
    }
    for (std::size_t c = 0; c < nc; ++c)
      if (applies(vocabulary[c], base))
        agree[i * nc + c] = agrees(x, m, results[i], j[i], vocabulary[c], base) ? 1 : 0;
      else
        agree[i * nc + c] = j[i].passing ? 1 : 0;  // neither explains nor contradicts
  });

  Diagnosis d;
  std::vector<CauseScore> all(nc);
  std::vector<std::vector<CauseScore>> per_group;
  std::map<std::string, std::size_t> group_index;
  for (std::size_t c = 0; c < nc; ++c) all[c].cause = &vocabulary[c];
  // Groups with a failing vector, in the order of first appearance.
  for (std::size_t i = 0; i < n; ++i)
    if (j[i].failing && group_index.emplace(vectors[i].group, d.groups.size()).second) {
      d.groups.emplace_back().group = vectors[i].group;
      per_group.push_back(all);
    }
  for (std::size_t i = 0; i < n; ++i) d.overall.unreproduced += std::size_t(unreproduced[i]);
  for (std::size_t i = 0; i < n; ++i) {
    if (!j[i].failing && !j[i].passing) continue;
    const auto g = group_index.find(vectors[i].group);
    if (j[i].failing) {
      ++d.overall.failing;
      if (g != group_index.end()) ++d.groups[g->second].failing;
    }
    for (std::size_t c = 0; c < nc; ++c) {
      const bool explains = j[i].failing && agree[i * nc + c];
      const bool contradicts = j[i].passing && !agree[i * nc + c];
      all[c].explains += explains;
      all[c].contradicts += contradicts;
      if (g != group_index.end()) {
        per_group[g->second][c].explains += explains;
        per_group[g->second][c].contradicts += contradicts;
      }
    }
  }
  rank(d.overall, all);
  for (std::size_t g = 0; g < d.groups.size(); ++g) rank(d.groups[g], per_group[g]);
  return d;
}

OJson vector_terms(const Vector& x, const Representation& base) {
  const Material m = vector_material(x);
  const BsdfOptions o = vector_options(x);
  const LutSet& luts = base.tables != nullptr ? *base.tables : LutSet::builtin();
  OJson components = OJson::object();
  for (const std::string& name : component_names(active_components(m)))
    components[name] = rgb_json(make_component_bsdf(name, m, luts, o)->eval(x.v, x.l) * std::abs(x.l.z));
  // The cosines in the core frame (the shading normal of docs/bsdf.md; the vectors' frame has z up).
  const double mu_v = std::min(std::abs(x.v.z), 1.0), mu_l = std::min(std::abs(x.l.z), 1.0);
  const Roughness2 ruv = anisotropic_roughness(m.roughness, m.anisotropy);
  const double r_uv = std::sqrt(ruv.u * ruv.v);
  const double f0 = std::clamp(f0_from_ior(1.0, m.ior) * m.specularTint.max_component(), 0.0, 1.0);
  const GgxDistribution ggx(roughness_to_alpha(ruv.u), roughness_to_alpha(ruv.v));
  OJson tables = {{"E_m(mu_v)", luts.E_m(mu_v, r_uv)},
                  {"E_m(mu_l)", luts.E_m(mu_l, r_uv)},
                  {"E_m_avg", luts.E_m_avg(r_uv)},
                  {"B_c f0", f0},
                  {"E(mu_v; r, f0)", luts.E_base(mu_v, r_uv, f0)},
                  {"E_avg(r, f0)", luts.E_base_avg(r_uv, f0)},
                  {"Lambda(v)", ggx.Lambda(x.v)},
                  {"Lambda(l)", ggx.Lambda(x.l)}};
  if (m.sheenColor.max_component() > 0) {
    const SheenLobe sheen(m.sheenColor, m.sheenRoughness, o.sheen_model, luts);
    tables["E_b(mu_v)"] = sheen.albedo(mu_v);
    tables["E_b(mu_l)"] = sheen.albedo(mu_l);
    tables["sheen_scaling"] = sheen.layer_scale(mu_v, mu_l);
    if (o.sheen_model == SheenModel::Main) {
      tables["sheen Lambda(v)"] = sheen_lambda(mu_v, sheen.alpha_b());
      tables["sheen Lambda(l)"] = sheen_lambda(mu_l, sheen.alpha_b());
    }
  }
  OJson with_cause = OJson::object();
  for (const Cause& c : causes())
    with_cause[c.name] = rgb_json(cause_bsdf(x, m, c, base).eval(x.v, x.l) * std::abs(x.l.z));
  return {{"components", std::move(components)}, {"tables", std::move(tables)}, {"with_cause", std::move(with_cause)}};
}

OJson terms_document(const std::vector<Vector>& vectors) {
  std::vector<OJson> terms(vectors.size());
  tbb::parallel_for(std::size_t(0), vectors.size(), [&](std::size_t i) {
    terms[i] = {{"id", vectors[i].id}};
    terms[i].update(vector_terms(vectors[i], {}));
  });
  OJson list = OJson::array();
  for (OJson& t : terms) list.push_back(std::move(t));
  return {{"format", "dspbr-conformance-terms"}, {"version", 1}, {"terms", std::move(list)}};
}

OJson ranking_json(const Ranking& r) {
  OJson list = OJson::array();
  for (const CauseScore& s : r.causes)
    list.push_back({{"cause", s.cause->name},
                    {"term", s.cause->term},
                    {"explains", s.explains},
                    {"contradicts", s.contradicts},
                    {"evidence", s.cause->evidence},
                    {"remedy", s.cause->remedy}});
  return {{"failing", r.failing}, {"unreproduced", r.unreproduced}, {"causes", std::move(list)}};
}

}  // namespace dspbr::conformance
