// Provenance of the outputs (apps/dspbr/provenance.h, README "Provenance"): printed documents
// carry the full version and the command line; table files record the project version and a
// command that does not depend on the output folder, so two runs into different folders write
// the same bytes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "dspbr/version.h"
#include "test_params_run.h"
#include "test_files.h"

TEST(Provenance, PrintedDocumentsCarryTheVersionAndTheCommandLine) {
  for (const std::string args : {"eval --view 0,0,1 --light 0,0.2,1 --tables published",
                                 "sample --view 0,0,1 --u 0.1,0.2,0.3", "params list --json",
                                 "params show " DSPBR_REFERENCE_DIR "/params-2025x.json glass --json",
                                 "scene analyze " DSPBR_SOURCE_DIR "/tests/data/gltf/materials.gltf --json"}) {
    const ToolRun r = run_dspbr(args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output);
    ASSERT_TRUE(j.contains("provenance")) << args;
    EXPECT_EQ(j["provenance"]["dspbr"], dspbr::version_string()) << args;
    const std::string command = j["provenance"]["command"];
    EXPECT_EQ(command, std::string(DSPBR_EXE) + " " + args) << args;
  }
  const nlohmann::json eval = nlohmann::json::parse(run_dspbr("eval --view 0,0,1 --light 0,0.2,1 --tables published").output);
  EXPECT_EQ(eval["provenance"]["settings"]["tables"], "published");
  EXPECT_EQ(eval["provenance"]["settings"]["transmission_compensation"], false);
  // Every option that changes a value is recorded: the transmission compensation too.
  const nlohmann::json comp = nlohmann::json::parse(
      run_dspbr("eval --view 0,0,1 --light 0,0.2,-1 --set transparency=1 --transmission-compensation").output);
  EXPECT_EQ(comp["provenance"]["settings"]["transmission_compensation"], true);
}

TEST(Provenance, TableFilesRecordTheProjectVersionAndTheSameBytesInAnyFolderWithAnyThreads) {
  const std::string a = ::testing::TempDir() + "/provenance_a", b = ::testing::TempDir() + "/provenance_b/deeper";
  for (const std::string& dir : {a, b}) {
    std::filesystem::remove_all(dir);
    const std::string threads = dir == a ? "1" : "2";
    const ToolRun r = run_dspbr("lut --tables GGX_E_avg --size GGX_E_avg=4 --samples 256 --formats json,png --threads " +
                                threads + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
  }
  const std::string text = read_all(a + "/dspbr_luts.json");
  EXPECT_EQ(text, read_all(b + "/dspbr_luts.json"));
  EXPECT_EQ(read_all(a + "/GGX_E_avg.png"), read_all(b + "/GGX_E_avg.png"));
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["dspbr_version"], DSPBR_PROJECT_VERSION);
  EXPECT_EQ(j["command"], "dspbr lut --tables GGX_E_avg --size GGX_E_avg=4 --samples 256 --formats json,png --out DIR");
  EXPECT_EQ(j["seed"], 1);
}
