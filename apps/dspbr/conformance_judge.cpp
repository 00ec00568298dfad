#include "conformance_judge.h"

#include <cstdio>
#include <optional>

#include "commands.h"
#include "report_script.h"
#include "dspbr/io/json_write.h"
#include "dspbr/conformance/vector_set.h"

namespace dspbr::cli {

void write_text(const OutputFolder& out, const std::string& name, const std::string& text) {
  write_text_file(out.staging() + "/" + name, text, out.dir() + "/" + name);
}

void add_representation_options(CLI::App* cmd, RepresentationOptions& o) {
  cmd->add_option("--tables", o.tables,
                  "Judge against the reference reading this table set: renderer (the vectors as written), published "
                  "(the published tables, multilinear), fits (the LUT-free fits), uncompensated (no energy "
                  "compensation), analytic (Karis 2014's albedo approximation); for an implementation that ships them "
                  "(docs/conformance.md)")
      ->capture_default_str();
  cmd->add_option("--min-roughness", o.min_roughness,
                  "The implementation clamps roughness and clearcoatRoughness to at least R: judge f_cos and pdf "
                  "against the reference with the same clamp (a mirror becomes its narrow lobe, judged with its "
                  "reflectance as the albedo; docs/conformance.md)")
      ->check(decimal_number())
      ->check(CLI::Range(0.0, 1.0));
}

conformance::DemoTables parse_tables_option(const std::string& tables) {
  try {
    return conformance::parse_demo_tables(tables);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--tables: ") + e.what());
  }
}

void expect_with(const RepresentationOptions& o, std::vector<conformance::Vector>& vectors,
                 nlohmann::ordered_json& provenance, const std::string& vectors_file) {
  const conformance::DemoTables tables = parse_tables_option(o.tables);
  provenance["tables"] = conformance::demo_tables_name(tables);
  provenance["min_roughness"] = o.min_roughness;
  if (tables == conformance::DemoTables::Renderer && o.min_roughness == 0) return;
  std::fprintf(stderr, "conformance: expectations of %zu vectors with the %s tables, roughness at least %g ...\n",
               vectors.size(), conformance::demo_tables_name(tables), o.min_roughness);
  try {
    conformance::expect_with(vectors, {&conformance::demo_table_set(tables), o.min_roughness});
  } catch (const std::runtime_error& e) {
    throw UsageError(vectors_file + ": " + e.what());
  }
}

void judge_results(const Judgement& j, OutputFolder& out, const std::vector<conformance::Vector>& vectors,
                   const std::vector<conformance::Result>& results, const nlohmann::ordered_json& provenance,
                   const RepresentationOptions& representation) {
  const conformance::Check check = conformance::check_results(vectors, results);
  // A check that judged nothing could not have failed: bad input, not a PASS.
  if (check.judged() == 0)
    throw UsageError(j.results + ": no result for any of the " + std::to_string(vectors.size()) +
                     (j.selection.groups.empty() && j.selection.components.empty() ? "" : " selected") + " vectors of " +
                     j.vectors);
  nlohmann::ordered_json report = conformance::check_report(vectors, results, check, provenance);
  std::optional<conformance::Diagnosis> diagnosis;
  if (!check.passed()) {
    std::fprintf(stderr, "conformance: diagnosing %zu failing vectors ...\n", check.failed);
    const conformance::Representation base{&conformance::demo_table_set(parse_tables_option(representation.tables)),
                                           representation.min_roughness};
    diagnosis = conformance::diagnose(vectors, results, check, base);
    report["diagnosis"] = conformance::ranking_json(diagnosis->overall);
    for (auto& g : report["groups"])
      for (const conformance::Ranking& r : diagnosis->groups)
        if (g["name"] == r.group) g["diagnosis"] = conformance::ranking_json(r);
    // The worst failing vectors term by term.
    for (auto& w : report["worst"])
      if (w["verdict"] == "FAIL")
        for (const conformance::Vector& x : vectors)
          if (x.id == w["id"]) {
            w["terms"] = conformance::vector_terms(x, base);
            break;
          }
  }
  write_text(out, "report.json", json_text(report, 1, "report.json"));
  if (!j.script.empty())
    run_report_script(j.python, j.script, out.staging(), j.out);
  else
    replace_earlier_pages(out, {"index.html"}, "report.json", check.passed() ? "PASS" : "FAIL");
  out.commit();

  std::printf("conformance: %s, %zu of %zu judged vectors pass", check.passed() ? "PASS" : "FAIL",
              check.judged() - check.failed, check.judged());
  if (check.not_supplied > 0) std::printf(" (%zu of %zu NOT SUPPLIED)", check.not_supplied, vectors.size());
  std::printf("; report in %s/%s\n", j.out.c_str(), j.script.empty() ? "report.json" : "index.html");
  std::printf("  %-28s %12s %6s %6s %6s %12s  %s\n", "group", "verdict", "PASS", "FAIL", "N/S", "worst ratio",
              "worst vector");
  for (const auto& g : report["groups"])
    std::printf("  %-28s %12s %6d %6d %6d %12.3g  %s\n", one_line(g["name"].get<std::string>()).c_str(),
                g["verdict"].get<std::string>().c_str(), g["passed"].get<int>(), g["failed"].get<int>(),
                g["not_supplied"].get<int>(), g["worst_ratio"].get<double>(), one_line(g["worst_id"].get<std::string>()).c_str());
  for (const auto& [name, q] : report["quantities"].items()) {
    if (q["not_judged"].get<int>() > 0)
      std::printf("  NOT JUDGED: %s of %d vectors (not in %s)\n", name.c_str(), q["not_judged"].get<int>(),
                  one_line(j.results).c_str());
    if (q["ignored"].get<int>() > 0)
      std::printf("  IGNORED: %s of %d results (their vectors have no %s expectation)\n", name.c_str(),
                  q["ignored"].get<int>(), name.c_str());
  }
  if (diagnosis) {
    // The causes printed: at most three, each explaining a tenth of the failures or more (the report
    // lists every cause that explains more than it is contradicted).
    const conformance::Ranking& d = diagnosis->overall;
    int shown = 0;
    for (const conformance::CauseScore& s : d.causes) {
      if (shown == 3 || 10 * s.explains < d.failing) break;
      if (shown++ == 0)
        std::printf("  likely causes of the %zu vectors whose f_cos or emission fails (docs/conformance.md, \"Diagnosis\"):\n",
                    d.failing);
      std::printf("  %d. %-22s explains %zu, contradicted by %zu: %s\n", shown, s.cause->name, s.explains, s.contradicts,
                  s.cause->evidence);
    }
    if (shown == 0 && d.failing > 0)
      std::printf("  no cause of the vocabulary explains a tenth of the %zu vectors whose f_cos or emission fails\n",
                  d.failing);
    if (d.unreproduced > 0)
      std::printf("  %zu vectors left out of the diagnosis: the reference does not give their expectations (an edited "
                  "or stale vector file?)\n",
                  d.unreproduced);
  }
  if (!check.passed())
    throw std::runtime_error(std::to_string(check.failed) + " of " + std::to_string(check.judged()) +
                             " judged conformance vectors fail (details in " + j.out + ")");
}

}  // namespace dspbr::cli
