// `dspbr conformance`: test vectors for implementers of DSPBR and the checker of their results
// (docs/conformance.md).
//   dspbr conformance generate --out DIR [--seed N] [--scenes FOLDER]   DIR/vectors.json, DIR/vectors.csv, DIR/terms.json
//   dspbr conformance check VECTORS RESULTS --out REPORT                 REPORT/report.json, index.html, plots/
//   dspbr conformance reference VECTORS --tables SET --out RESULTS.json  the reference's results with other tables
// check exits 0 when every vector passes, 1 when one fails, 2 on bad input (one line naming the
// file and the record).
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <tbb/global_control.h>

#include "commands.h"
#include "conformance_judge.h"
#include "interrupt_cleanup.h"
#include "provenance.h"
#include "report_script.h"
#include "dspbr/conformance/checker.h"
#include "dspbr/conformance/demo_tables.h"
#include "dspbr/conformance/diagnosis.h"
#include "dspbr/conformance/results.h"
#include "dspbr/conformance/vector_file.h"
#include "dspbr/conformance/vector_set.h"
#include "dspbr/io/atomic_file.h"
#include "dspbr/io/json_write.h"
#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/validate/provenance.h"

namespace dspbr::cli {

namespace {

using OJson = nlohmann::ordered_json;

struct GenerateArgs {
  std::string out;
  std::string scenes;  // "": the validation scenes next to the binary
  bool no_scenes = false;
  conformance::GenerateSettings settings;
  int threads = 0;
};

struct ReferenceArgs {
  std::string vectors, out, tables = "renderer";
};

struct CheckArgs {
  std::string vectors, results, out;
  RepresentationOptions representation;
  std::string python = kDefaultPython;
  bool html = true, require_all = false;
  conformance::Selection selection;
};

// vectors.json with one vector per line (diff-friendly, still strict JSON).
std::string vectors_text(const OJson& doc) {
  if (const auto p = non_finite_path(doc))
    throw std::runtime_error("vectors.json: the value at " + *p + " is not finite; nothing written");
  std::string s = "{\"format\": " + doc["format"].dump() + ", \"version\": " + doc["version"].dump() +
                  ",\n \"provenance\": " + doc["provenance"].dump() + ",\n \"vectors\": [\n";
  const OJson& vs = doc["vectors"];
  for (std::size_t i = 0; i < vs.size(); ++i) s += "  " + vs[i].dump() + (i + 1 < vs.size() ? ",\n" : "\n");
  return s + "]}\n";
}

void run_generate(const GenerateArgs& a) {
  std::unique_ptr<tbb::global_control> threads;
  if (a.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(a.threads));
  conformance::GenerateSettings settings = a.settings;
  std::string scenes_name = a.scenes;  // as recorded: the folder as given, or the built-in scenes' name
  if (a.no_scenes) {
    scenes_name = "none";
  } else if (a.scenes.empty()) {
    settings.scenes_dir = shared_path("scenes/sphere", "; --scenes FOLDER names the scenes, --no-scenes leaves them out");
    scenes_name = "validation scenes (share/dspbr/scenes/sphere)";
  } else {
    settings.scenes_dir = a.scenes;
  }
  InterruptCleanup cleanup(a.out);  // the handlers first, then the folder
  OutputFolder& out = cleanup.out();
  std::vector<conformance::Vector> vectors;
  try {
    vectors = conformance::generate_vectors(settings);
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string("--scenes: ") + e.what());
  }
  // Provenance without the git hash, the --out folder or --threads: the same settings give the
  // same bytes at any commit of the same version and with any thread count.
  const OJson provenance{
      {"dspbr_version", validate::project_version()},
      {"command", reproducible_command()},
      {"settings", {{"seed", a.settings.seed}, {"directions", a.settings.directions},
                    {"scenes", scenes_name}, {"albedo", a.settings.albedo}}},
      {"reference", {{"tables", LutSet::builtin_name(LutLayout::Renderer)}, {"options", "defaults but a vector's options"},
                     {"table_error", conformance::kTableError}, {"float_relative", conformance::kFloatRelative},
                     {"float_absolute", conformance::kFloatAbsolute},
                     {"thin_film_relative", conformance::kThinFilmRelative},
                     {"albedo_agreement", conformance::kAlbedoAgreement}}},
      {"conventions", "docs/bsdf.md: local frame (normal +z), v and l away from the surface, f_cos = f(v, l) |l.z|"}};
  const std::string text = vectors_text(conformance::vectors_document(vectors, provenance));
  // A set its own readers refuse is bad input, not a success (docs/limits.md: vector files are read
  // up to limits::kDocumentBytes).
  if (text.size() > limits::kDocumentBytes)
    throw UsageError("the vector set would be " + bytes_text(text.size()) + ", larger than the limit of " +
                     bytes_text(limits::kDocumentBytes) + " of the files that read it (docs/limits.md): use fewer --directions");
  write_text(out, "vectors.json", text);
  write_text(out, "vectors.csv", conformance::vectors_csv(vectors));
  write_text(out, "terms.json", json_text(conformance::terms_document(vectors), -1, "terms.json") + "\n");
  out.commit();
  std::size_t delta = 0, albedo = 0;
  for (const auto& v : vectors) delta += v.delta.empty() ? 0 : 1, albedo += v.albedo ? 1 : 0;
  std::printf("%zu vectors (%zu with delta lobes, %zu with an albedo) -> %s/vectors.json, %s/vectors.csv, %s/terms.json\n",
              vectors.size(), delta, albedo, a.out.c_str(), a.out.c_str(), a.out.c_str());
}

void run_check(const CheckArgs& a) {
  parse_tables_option(a.representation.tables);  // before any work
  const std::string script = a.html ? report_script("conformance_report.py", a.python) : std::string();
  std::vector<conformance::Vector> vectors;
  std::vector<conformance::Result> results;
  try {
    vectors = conformance::read_vectors(a.vectors);
    results = conformance::match_results(vectors, conformance::read_results(a.results), a.results, a.vectors);
    conformance::select_vectors(a.selection, vectors, results);
    // --require-all: every vector judged, i.e. of the selection (--groups/--components), has its f cos.
    const bool selected = !a.selection.groups.empty() || !a.selection.components.empty();
    if (a.require_all)
      conformance::require_f_cos(vectors, results, a.results, selected ? "the selection of " + a.vectors : a.vectors);
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  OJson provenance = output_provenance();
  provenance["vectors"] = a.vectors;
  provenance["results"] = a.results;
  // The output folder before the work of --tables/--min-roughness: an unwritable one is refused first.
  InterruptCleanup cleanup(a.out);  // the handlers first, then the folder
  expect_with(a.representation, vectors, provenance, a.vectors);
  Judgement j{a.vectors, a.results, a.out, a.python, script, a.selection};
  judge_results(j, cleanup.out(), vectors, results, provenance, a.representation);
}

// The results of the reference BSDF reading another table set (f cos and pdf; the quantities that
// do not depend on the tables are left out): the demonstrations' implementations.
void run_reference(const ReferenceArgs& a) {
  check_output_file(a.out, "--out");
  std::error_code ec;
  if (std::filesystem::equivalent(a.out, a.vectors, ec))
    throw UsageError("--out: '" + quote_input(a.out) + "' is the vector file itself; name another file");
  const conformance::DemoTables tables = parse_tables_option(a.tables);
  std::vector<conformance::Vector> vectors;
  try {
    vectors = conformance::read_vectors(a.vectors);
  } catch (const std::runtime_error& e) {
    throw UsageError(e.what());
  }
  const LutSet& luts = conformance::demo_table_set(tables);
  std::vector<conformance::Result> results;
  for (const conformance::Vector& v : vectors) {
    conformance::Evaluation e;
    try {
      e = conformance::evaluate(v, luts);
    } catch (const std::exception& ex) {  // an invalid instance or options
      throw UsageError(a.vectors + ": vector '" + v.id + "': " + ex.what());
    }
    results.push_back({v.id, e.f_cos, e.pdf, std::nullopt, std::nullopt, std::nullopt});
  }
  write_text_atomically(a.out, json_text(conformance::results_document(results), -1, a.out) + "\n");
  std::printf("%zu results of the reference with the %s tables -> %s\n", vectors.size(), a.tables.c_str(), a.out.c_str());
}

}  // namespace

void add_conformance_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("conformance", "Conformance kit: test vectors for DSPBR implementations and their checker");
  cmd->require_subcommand(1);

  auto g = std::make_shared<GenerateArgs>();
  auto* gen = cmd->add_subcommand("generate", "Write the conformance vectors: DIR/vectors.json, DIR/vectors.csv and their per-term expectations "
                                  "DIR/terms.json");
  gen->add_option("--out", g->out, "Output folder")->required();
  gen->add_option("--seed", g->settings.seed, "Seed of the directions (same seed -> same bytes)")
      ->capture_default_str()
      ->transform(non_negative_integer());
  gen->add_option("--directions", g->settings.directions,
                  "Pairs of directions per material (a set beyond 16 MB, the size its readers take, is refused: "
                  "the default set is 2.7 MB)")
      ->capture_default_str()
      ->transform(decimal_integer(1, 1000, "a number of direction pairs"));
  gen->add_option("--scenes", g->scenes,
                  "Folder of .gltf scenes whose materials join the set (default: the validation scenes, "
                  "data/dspbr/scenes/sphere, installed with dspbr)");
  gen->add_flag("--no-scenes", g->no_scenes, "Only the built-in materials (no scene materials)");
  gen->add_flag("--no-albedo", [g](int64_t) { g->settings.albedo = false; },
                "Leave out the directional albedos (a quadrature per material: most of the time)");
  gen->add_option("--threads", g->threads, "Worker threads (0: all cores); the vectors do not depend on it")
      ->capture_default_str()
      ->transform(thread_count());
  gen->callback([g] { run_generate(*g); });

  auto c = std::make_shared<CheckArgs>();
  auto* chk = cmd->add_subcommand(
      "check", "Judge an implementation's results against the vectors; writes REPORT/report.json and index.html "
               "(exit 0: all pass, 1: a failure, 2: bad input)");
  chk->add_option("VECTORS", c->vectors, "vectors.json written by `dspbr conformance generate`")->required();
  chk->add_option("RESULTS", c->results,
                  "Results: JSON {\"results\": [{\"id\", \"f_cos\", [\"pdf\"], [\"albedo\"], ...}]} or CSV "
                  "id,f_cos_r,f_cos_g,f_cos_b[,pdf][,albedo_r,albedo_g,albedo_b]")
      ->required();
  chk->add_option("--out", c->out, "Report folder")->required();
  chk->add_option("--python", c->python, "Python interpreter with numpy, matplotlib and jinja2")->capture_default_str();
  chk->add_flag("--no-html", [c](int64_t) { c->html = false; }, "Write only report.json");
  add_list_option(chk, "--groups", c->selection.groups,
                  "Judge only the vectors of these groups (comma-separated: plain_metal, sheen, ...; the report "
                  "lists them)");
  add_list_option(chk, "--components", c->selection.components,
                  "Judge only the vectors whose material has one of these components (comma-separated: "
                  "clearcoat, sheen, ...)");
  add_representation_options(chk, c->representation);
  chk->add_flag("--require-all", c->require_all,
                "Every vector judged needs a result with its f_cos (by default a vector without one is NOT "
                "SUPPLIED and not judged); the other quantities (pdf, albedo, emission, delta) left out or null "
                "are NOT SUPPLIED either way, and counted in the summary");
  chk->callback([c] { run_check(*c); });

  auto r = std::make_shared<ReferenceArgs>();
  auto* ref = cmd->add_subcommand(
      "reference", "Write the results of the reference BSDF reading another table set (the demonstrations of "
                   "docs/conformance.md): f_cos and pdf of every vector");
  ref->add_option("VECTORS", r->vectors, "vectors.json written by `dspbr conformance generate`")->required();
  ref->add_option("--tables", r->tables,
                  "renderer (the reference), published, fits (fits/dspbr_fits.hpp), uncompensated or analytic "
                  "(Karis 2014's albedo approximation)")
      ->capture_default_str();
  ref->add_option("--out", r->out, "Results file (JSON)")->required();
  ref->callback([r] { run_reference(*r); });

  add_conformance_run_command(*cmd);
}

}  // namespace dspbr::cli
