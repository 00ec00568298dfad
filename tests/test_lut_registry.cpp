// The table registry (tables/table_registry.h): it is what the generator, the readers, the CLI and
// the scene analysis use, and no other source compares a table name as a string.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"
#include "dspbr/lutgen/generate.h"
#include "dspbr/lutgen/lut_io.h"
#include "dspbr/lutgen/renderer_io.h"
#include "dspbr/tables/renderer_luts.h"
#include "dspbr/tables/table_registry.h"
#include "test_params_run.h"

namespace fs = std::filesystem;
using namespace dspbr;

TEST(LutRegistry, IdsIndexTheRegistryAndNamesAreUnique) {
  std::set<std::string> names;
  for (size_t i = 0; i < lut_registry().size(); ++i) {
    const LutInfo& t = lut_registry()[i];
    EXPECT_EQ(size_t(t.id), i) << t.name;
    EXPECT_TRUE(names.insert(t.name).second) << t.name;
    EXPECT_EQ(&lut_info(t.id), &t);
    EXPECT_NE(t.layouts, 0u) << t.name;
    if (t.layouts & kPublishedLayout) {
      EXPECT_EQ(t.axes.size(), t.size.size()) << t.name;
      EXPECT_EQ(t.average, std::find(t.axes.begin(), t.axes.end(), std::string("cos_theta")) == t.axes.end())
          << t.name;
    }
  }
  // DSPBR 2025x's six published tables, then the four glass tables.
  EXPECT_EQ(lut_names(kPublishedLayout),
            (std::vector<std::string>{"GGX_E", "GGX_E_avg", "Base_E", "Base_E_avg", "Sheen_E", "Sheen_ash_E", "Glass_E",
                                      "Glass_inv_E", "Glass_E_avg", "Glass_inv_E_avg"}));
  // The renderer layout's order (its file and generated code follow it; the committed luts/ too).
  EXPECT_EQ(lut_names(kRendererLayout),
            (std::vector<std::string>{"GGX_E", "GGX_beta", "GGX_E_avg", "GGX_B_avg", "Sheen_E", "Sheen_ash_E", "Glass_E",
                                      "Glass_inv_E", "Glass_E_avg", "Glass_inv_E_avg"}));
  const nlohmann::ordered_json committed = nlohmann::ordered_json::parse(
      read_file((fs::path(DSPBR_SOURCE_DIR) / "luts/dspbr_renderer_luts.json").string(), limits::kDocumentBytes));
  std::vector<std::string> in_file;
  for (const auto& item : committed["tables"].items()) in_file.push_back(item.key());
  EXPECT_EQ(in_file, lut_names(kRendererLayout));
}

// What the generator makes is what the registry declares: names, axis names and order, sizes.
TEST(LutRegistry, GeneratedTablesHaveTheRegistrysAxes) {
  LutOptions opt;
  opt.tables = lut_table_names();
  opt.integrator = Integrator::Qmc;
  opt.samples = 16;
  opt.randomizations = 2;
  opt.target_error = 0;
  opt.progress = false;
  for (const std::string& t : opt.tables) opt.sizes[t] = std::vector<int>(published_lut(t).axes.size(), 2);
  const std::vector<Table> tables = generate_luts(opt);
  ASSERT_EQ(tables.size(), opt.tables.size());
  for (const Table& t : tables) {
    const LutInfo& info = published_lut(t.name);
    ASSERT_EQ(t.axes.size(), info.axes.size()) << t.name;
    for (size_t d = 0; d < t.axes.size(); ++d) EXPECT_EQ(t.axes[d].name, info.axes[d]) << t.name;
  }
  // The renderer layout's tables are the registry's renderer tables.
  for (const char* n : RendererLuts::names()) EXPECT_NE(find_lut(n, kRendererLayout), nullptr) << n;
  for (const char* n : RendererLuts::glass_names()) EXPECT_TRUE(require_lut(n, kRendererLayout).glass) << n;
}

TEST(LutRegistry, UnknownNamesListEveryTable) {
  try {
    (void)published_lut("GGX_F");
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "unknown table 'GGX_F'; did you mean 'GGX_E'? (known: " + lut_names_list(kPublishedLayout) + ")");
  }
  // GGX_beta is a renderer table only.
  EXPECT_EQ(find_lut("GGX_beta", kPublishedLayout), nullptr);
  EXPECT_NE(find_lut("GGX_beta", kRendererLayout), nullptr);
  const ToolRun r = run_dspbr("lut --out " + ::testing::TempDir() + "/registry_out --tables GGX_E,Foo");
  EXPECT_EQ(r.status, 2) << r.output;
  for (const std::string& n : lut_names(kPublishedLayout)) EXPECT_NE(r.output.find(n), std::string::npos) << n;
  EXPECT_EQ(count_lines_with(r.output, "unknown table 'Foo'"), 1) << r.output;
}

TEST(LutRegistry, SizeOfATableNotGeneratedIsRefused) {
  const fs::path out = fs::path(::testing::TempDir()) / "registry_size_out";
  const ToolRun r = run_dspbr("lut --out " + out.string() + " --tables GGX_E --size Base_E=4x4x4");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("a size is given for Base_E, which is not being generated (tables: GGX_E)"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out / "dspbr_luts.json"));
}

// The readers check a file against the registry: table names, axis names and order, version.
TEST(LutRegistry, TableFilesAreCheckedAgainstTheSchema) {
  const nlohmann::json good = {
      {"format", "dspbr_luts"},
      {"version", 1},
      {"tables",
       {{"GGX_E",
         {{"axes",
           {{{"name", "roughness"}, {"size", 2}, {"lo", 0}, {"hi", 1}, {"grid", "cell"}},
            {{"name", "cos_theta"}, {"size", 2}, {"lo", 0}, {"hi", 1}, {"grid", "cell"}}}},
          {"values", {1, 1, 1, 1}}}}}}};
  EXPECT_EQ(read_lut_json_text(good.dump(), "good.json").size(), 1u);
  auto refused = [&](const nlohmann::json& j, const std::string& message) {
    try {
      (void)read_lut_json_text(j.dump(), "t.json");
      ADD_FAILURE() << "accepted: " << message;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "'t.json': " + message);
    }
  };
  nlohmann::json unknown = good;
  unknown["tables"]["GGX_F"] = good["tables"]["GGX_E"];
  refused(unknown, "tables.GGX_F: unknown table (known: " + lut_names_list(kPublishedLayout) + ")");
  nlohmann::json swapped = good;
  std::swap(swapped["tables"]["GGX_E"]["axes"][0], swapped["tables"]["GGX_E"]["axes"][1]);
  refused(swapped, "tables.GGX_E.axes[0].name must be roughness");
  nlohmann::json renamed = good;
  renamed["tables"]["GGX_E"]["axes"][1]["name"] = "cos";
  refused(renamed, "tables.GGX_E.axes[1].name must be cos_theta");
  for (const nlohmann::json& v : {nlohmann::json(2), nlohmann::json("1"), nlohmann::json(nullptr)}) {
    nlohmann::json other = good;
    other["version"] = v;
    refused(other, "\"version\" must be 1 (this build reads table files of that version)");
  }
  nlohmann::json missing = good;
  missing.erase("version");
  refused(missing, "\"version\" must be 1 (this build reads table files of that version)");
  // The renderer layout's reader: the committed set passes, an unknown table or version does not.
  nlohmann::json ren = nlohmann::json::parse(read_file((fs::path(DSPBR_SOURCE_DIR) / "luts/dspbr_renderer_luts.json").string(), limits::kDocumentBytes));
  EXPECT_NO_THROW((void)read_renderer_json_value(ren, "ren.json"));
  nlohmann::json ren_unknown = ren;
  ren_unknown["tables"]["Base_E"] = ren["tables"]["GGX_E"];  // a published table only
  EXPECT_THROW((void)read_renderer_json_value(ren_unknown, "ren.json"), std::runtime_error);
  nlohmann::json ren_version = ren;
  ren_version["version"] = 2;
  EXPECT_THROW((void)read_renderer_json_value(ren_version, "ren.json"), std::runtime_error);
}

// No table name is written as a string literal in the sources outside the registry (the tests
// and generated sources aside): everything else gets names from it.
TEST(LutRegistry, NoTableNameLiteralOutsideTheRegistry) {
  std::string alternatives;
  for (const LutInfo& t : lut_registry()) alternatives += (alternatives.empty() ? "" : "|") + std::string(t.name);
  // A literal that is a table name, or starts with one followed by a space, comma or quote.
  const std::regex literal("\"(" + alternatives + ")[\" ,]");
  const fs::path root(DSPBR_SOURCE_DIR);
  int files = 0;
  for (const char* dir : {"src", "apps", "python"}) {
    for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
      if (e.path().filename() == "table_registry.cpp") continue;
      ++files;
      std::istringstream in(read_file(e.path().string(), limits::kDocumentBytes));
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        const std::string code = line.substr(0, line.find("//"));  // comments may name tables
        EXPECT_FALSE(std::regex_search(code, literal)) << e.path().string() << ":" << n << ": " << line;
      }
    }
  }
  EXPECT_GT(files, 50);
}

// Progress: one plain line per table when stderr is not a terminal; --quiet silences it.
TEST(LutRegistry, ProgressLinePerTableAndQuiet) {
  const fs::path out = fs::path(::testing::TempDir()) / "registry_progress_out";
  const std::string args = "lut --out " + out.string() +
                           " --tables GGX_E_avg,Sheen_E --size GGX_E_avg=4 --size Sheen_E=4x4 --formats json";
  const ToolRun r = run_dspbr(args);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(count_lines_with(r.output, "[1/2] GGX_E_avg cells: 4/4 (100%) in"), 1) << r.output;
  EXPECT_EQ(count_lines_with(r.output, "[2/2] Sheen_E cells: 16/16 (100%) in"), 1) << r.output;
  EXPECT_EQ(r.output.find('\r'), std::string::npos) << "no terminal control in a log";
  const ToolRun q = run_dspbr(args + " --quiet");
  ASSERT_EQ(q.status, 0) << q.output;
  EXPECT_EQ(q.output.find("cells:"), std::string::npos) << q.output;
  fs::remove_all(out);
}
