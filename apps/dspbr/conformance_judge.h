// The verdict and report shared by `dspbr conformance check` (results from a file) and
// `dspbr conformance run` (results from a shader on a Vulkan device): judges the results
// (dspbr/conformance/checker.h), writes REPORT/report.json and, with a script, index.html and
// plots/, prints the summary per group, and throws when a vector fails (exit 1) or when nothing
// could be judged (UsageError, exit 2: a check that could not have failed is not a PASS).
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "dspbr/conformance/checker.h"
#include "dspbr/conformance/demo_tables.h"
#include "dspbr/conformance/diagnosis.h"
#include "dspbr/conformance/results.h"
#include "dspbr/conformance/vector.h"
#include "dspbr/io/output_folder.h"

namespace dspbr::cli {

// Writes `text` to the file `name` of the run's staging folder; std::runtime_error naming
// out.dir()/name and the system's reason when it cannot.
void write_text(const OutputFolder& out, const std::string& name, const std::string& text);

inline constexpr const char* kDefaultPython = "/usr/bin/python3";

struct Judgement {
  std::string vectors, results;  // as named in messages and the report
  std::string out;               // the report folder
  std::string python, script;    // script "": report.json alone (--no-html)
  conformance::Selection selection;
};

// --tables and --min-roughness of `check` and `run`: how the implementation represents DSPBR
// (conformance::Representation). The defaults judge against the vectors as written.
struct RepresentationOptions {
  std::string tables = "renderer";  // conformance/demo_tables.h
  double min_roughness = 0;
};
void add_representation_options(CLI::App* cmd, RepresentationOptions& o);
// --tables, parsed before any work (UsageError naming the option when it names no set).
conformance::DemoTables parse_tables_option(const std::string& tables);
// Other than the defaults: the vectors' expectations recomputed for them (conformance::expect_with;
// a progress line on stderr); provenance["tables"] and ["min_roughness"] record them.
void expect_with(const RepresentationOptions& o, std::vector<conformance::Vector>& vectors,
                 nlohmann::ordered_json& provenance, const std::string& vectors_file);

// Writes the report into `out` (the run's folder, interrupt_cleanup.h; the caller may have written
// other files into its staging folder) and commits it. When a vector fails, the report's
// `diagnosis` and each failing group's ranks the likely causes (conformance/diagnosis.h), with the
// reference made as `representation` says plus each cause; the summary prints the first ones.
void judge_results(const Judgement& j, OutputFolder& out, const std::vector<conformance::Vector>& vectors,
                   const std::vector<conformance::Result>& results, const nlohmann::ordered_json& provenance,
                   const RepresentationOptions& representation);

// `dspbr conformance run` (cmd_conformance_run.cpp), registered on `dspbr conformance`.
void add_conformance_run_command(CLI::App& conformance);

}  // namespace dspbr::cli
