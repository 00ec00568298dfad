// Conventions of the `dspbr` command as a whole (apps/dspbr/main.cpp): --version, exit codes
// (0 success, 1 checks failed, 2 bad input or usage), one-line errors naming the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "dspbr/version.h"
#include "test_params_run.h"

TEST(Cli, VersionPrintsProjectVersionAndGitDescription) {
  const ToolRun r = run_dspbr("--version");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, std::string("dspbr ") + dspbr::version_string() + "\n");
  // "<version>" or "<version> (<describe>)": an abbreviated hash, optionally after a tag and
  // before "-dirty".
  const std::regex form("dspbr " + std::regex_replace(DSPBR_PROJECT_VERSION, std::regex("\\."), "\\.") +
                        "( \\(([^ ]+-g)?[0-9a-f]{4,40}(-dirty)?\\))?\n");
  EXPECT_TRUE(std::regex_match(r.output, form)) << r.output;
}

namespace {


std::string temp_path(const std::string& name) { return ::testing::TempDir() + "/cli_" + name; }

}  // namespace

TEST(Cli, ParseErrorsExitWith2AndHelpWith0) {
  expect_usage_error("lut --bogus", "--bogus");
  expect_usage_error("eval --view 0,0,1", "--light is required");
  expect_usage_error("lut --seed abc", "--seed");
  expect_usage_error("", "A subcommand is required");
  for (const char* help : {"--help", "--help-all", "params --help", "params list --help"}) {
    const ToolRun r = run_dspbr(help);
    EXPECT_EQ(r.status, 0) << help << "\n" << r.output;
    EXPECT_NE(r.output.find("Usage:"), std::string::npos) << help << "\n" << r.output;
  }
}

TEST(Cli, UnknownSubcommandSuggestsTheNearestName) {
  expect_usage_error("lutt", "unknown subcommand 'lutt'; did you mean 'lut'?");
  expect_usage_error("valdate --quick", "unknown subcommand 'valdate'; did you mean 'validate'?");
  expect_usage_error("params lst", "unknown subcommand 'lst'; did you mean 'list'?");
  expect_usage_error("scene analyse x.gltf", "unknown subcommand 'analyse'; did you mean 'analyze'?");
  expect_usage_error("render", "unknown subcommand 'render' (choose from lut, eval, sample, validate, fit, params, scene, conformance, shader)");
}

TEST(Cli, DirectoryGivenAsAFileIsNamed) {
  const std::string dir = temp_path("folder.gltf");
  std::filesystem::create_directories(dir);
  const std::string message = dir + " is a directory";
  // (scene analyze takes folders: this one holds no scene.)
  expect_usage_error("scene analyze " + dir, dir + ": a folder without .gltf or .glb files");
  expect_usage_error("lut --scene " + dir + " --out " + temp_path("lut_out"), message);
  expect_usage_error("eval --material " + dir + " --view 0,0,1 --light 0,0,1", message);
  expect_usage_error("params list " + dir, message);
  expect_usage_error("params show " + dir + " glass", message);
  expect_usage_error("validate --luts " + dir, dir);
  const ToolRun check = run_dspbr("params check " + dir);
  EXPECT_EQ(check.status, 2) << check.output;
  EXPECT_EQ(count_lines_with(check.output, message), 1) << check.output;
}

TEST(Cli, PngRenamedGltfIsNamedAsSuch) {
  const std::string png = temp_path("image.gltf");
  std::ofstream(png, std::ios::binary) << std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  expect_usage_error("scene analyze " + png, png + " is not a glTF file (it starts like a PNG image)");
  expect_usage_error("lut --scene " + png + " --out " + temp_path("lut_out"), png + " is not a glTF file");
}

TEST(Cli, NegativeOrOversizedUnsignedOptionsAreRefused) {
  const std::string out = " --out " + temp_path("refused");
  expect_usage_error("lut --seed -1 --tables GGX_E --size GGX_E=4x4 --formats json" + out,
                     "--seed: must be an integer from 0 to 18446744073709551615 (decimal digits), got '-1'");
  expect_usage_error("lut --seed 18446744073709551616 --tables GGX_E --size GGX_E=4x4 --formats json" + out,
                     "--seed: must be an integer from 0 to 18446744073709551615 (decimal digits), got '18446744073709551616'");
  expect_usage_error("lut --samples -5 --tables GGX_E --size GGX_E=4x4 --formats json" + out, "--samples:");
  expect_usage_error("fit --quick --seed -1" + out, "--seed:");
  expect_usage_error("validate --quick --no-html --seed -1" + out, "--seed:");
}

TEST(Cli, ThreadCountAboveTheLimitIsRefused) {
  const std::string out = " --out " + temp_path("refused");
  expect_usage_error("lut --threads 2147483647 --tables GGX_E --size GGX_E=4x4 --formats json" + out,
                     "--threads: must be a thread count (0: all cores) from 0 to 1024 (decimal digits), got '2147483647'");
  expect_usage_error("lut --threads -1 --tables GGX_E --size GGX_E=4x4 --formats json" + out, "--threads:");
  expect_usage_error("fit --quick --threads 1025" + out, "--threads:");
}

// A mistyped option or parameter gets the nearest valid name (within 2 edits), whatever else is
// missing from the command line.
TEST(Cli, UnknownOptionsAndParametersGetTheNearestName) {
  expect_usage_error("eval --veiw 0,0,1 --light 0,0,1", "unknown option '--veiw' of 'eval'; did you mean '--view'?");
  expect_usage_error("lut --out x --tabels GGX_E", "unknown option '--tabels' of 'lut'; did you mean '--tables'?");
  expect_usage_error("eval --view 0,0,1 --light 0,0,1 --zzzzzzz", "unknown option '--zzzzzzz' of 'eval' (--help lists");
  expect_usage_error("eval --view 0,0,1 --light 0,0,1 --set rougness=0.3",
                     "unknown material parameter 'rougness'; did you mean 'roughness'?");
  // --opt=value forms are names too; a known option with a value passes through to CLI11.
  expect_usage_error("eval --veiw=0,0,1 --light 0,0,1", "did you mean '--view'?");
  // A name in another case is offered itself, before longer names it begins (the tenth fresh
  // tester's pass: 'ggx_e' was offered 'GGX_E_avg').
  expect_usage_error("lut --out x --tables GGX_E --size ggx_e=16x16", "unknown table 'ggx_e'; did you mean 'GGX_E'?");
  expect_usage_error("lut --out x --tables ggx_e_AVG", "unknown table 'ggx_e_AVG'; did you mean 'GGX_E_avg'?");
  // --size takes no spaces, anywhere (they were trimmed around the numbers only).
  for (const char* size : {"' GGX_E=16x16'", "'GGX_E=16 x16'", "'GGX_E= 16x16'"})
    expect_usage_error(std::string("lut --out x --tables GGX_E --size ") + size, "holds a space: give NAME=SIZE without spaces");
}

// Colour parameters take one number (grey) or three, on the command line as in files.
TEST(Cli, ColourParametersTakeOneOrThreeNumbers) {
  const ToolRun grey = run_dspbr("eval --view 0,0,1 --light 0,0.2,1 --set albedo=0.5");
  const ToolRun three = run_dspbr("eval --view 0,0,1 --light 0,0.2,1 --set albedo=0.5,0.5,0.5");
  ASSERT_EQ(grey.status, 0) << grey.output;
  ASSERT_EQ(three.status, 0) << three.output;
  auto f = [](const std::string& out) { return nlohmann::json::parse(out)["f"]; };
  EXPECT_EQ(f(grey.output), f(three.output));
  expect_usage_error("eval --view 0,0,1 --light 0,0,1 --set albedo=0.5,0.5",
                     "parameter 'albedo' expects one number (grey) or 3 comma-separated numbers (r,g,b), got '0.5,0.5'");
  // A material instance file: a number is grey as well.
  const std::string path = temp_path("grey_instance.json");
  std::ofstream(path) << R"({"material": "generic", "values": {"albedo": 0.5}})";
  const ToolRun file = run_dspbr("eval --material " + path + " --view 0,0,1 --light 0,0.2,1");
  ASSERT_EQ(file.status, 0) << file.output;
  EXPECT_EQ(f(file.output), f(three.output));
  // Vectors stay three numbers.
  expect_usage_error("eval --view 0,0,1 --light 0,0,1 --set normal=0.5", "expects 3 comma-separated numbers (x,y,z)");
}

// `params show MATERIAL` reads the built-in definitions, as documented (docs/params.md).
TEST(Cli, ParamsShowDefaultsToTheBuiltInDefinitions) {
  const ToolRun builtin = run_dspbr("params show glass");
  const ToolRun file = run_dspbr("params show " DSPBR_REFERENCE_DIR "/params-2025x.json glass");
  ASSERT_EQ(builtin.status, 0) << builtin.output;
  EXPECT_EQ(builtin.output, file.output);
  EXPECT_NE(builtin.output.find("roughness"), std::string::npos);
}
