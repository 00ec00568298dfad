// Untrusted input (docs/limits.md: "Confinement", "Input files", "Messages", "Numbers on the
// command line"): a glTF's URIs never reach outside its folder and no message tells anything
// about a file there; glTF fields are checked as the schema says; no non-finite number is
// written; command-line numbers are decimal; a refused run leaves no folder behind. Every input
// is built by the test.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <regex>
#include <string>

#include "dspbr/conformance/results.h"
#include "dspbr/gltf/gltf_file.h"
#include "dspbr/io/decimal.h"
#include "dspbr/gltf/gltf_uri.h"
#include "test_params_run.h"
#include "test_files.h"

using namespace dspbr;
using Json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

fs::path fresh(const std::string& name) {
  const fs::path p = fs::path(::testing::TempDir()) / ("untrusted_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

// A minimal glTF 2.0 asset: one 24-byte buffer at `uri`, one view, one VEC3 float accessor of
// `count` elements, one mesh using material 0.
Json asset(const std::string& uri, const Json& count = 2) {
  return Json{{"asset", {{"version", "2.0"}}},
              {"buffers", {{{"byteLength", 24}, {"uri", uri}}}},
              {"bufferViews", {{{"buffer", 0}, {"byteLength", 24}}}},
              {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", count}, {"type", "VEC3"}}}},
              {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 0}}}}}}},
              {"materials", {{{"name", "m"}}}}};
}

}  // namespace

// Each URI is resolved inside the glTF's folder, component by component: what stays inside is
// the file it names, what leaves (absolute, "..", percent-encoded "..", through a link) is refused.
TEST(Untrusted, UrisResolveOnlyInsideTheGltfsFolder) {
  const fs::path root = fresh("uris");
  const fs::path scene = root / "scene";
  write(scene / "sub" / "a.bin", std::string(24, 'a'));
  write(root / "secret.bin", std::string(24, 's'));
  fs::create_directory_symlink("sub", scene / "in");              // relative, stays inside
  fs::create_directory_symlink(scene / "sub", scene / "in_abs");  // absolute, stays inside
  fs::create_directory_symlink("..", scene / "out");              // relative, leaves
  fs::create_symlink(root / "secret.bin", scene / "out_abs.bin");  // absolute, leaves
  fs::create_symlink("loop", scene / "loop");
  const std::string gltf = (scene / "s.gltf").string();
  const std::string canon = fs::canonical(scene).string();
  // One resolver for every URI, as a glTF's reader does (the folder is found once), and the
  // one-URI function beside it.
  gltf::LocalUriResolver resolver(gltf);
  auto resolved = [&](const std::string& uri) { return resolver.resolve(uri); };
  EXPECT_EQ(gltf::resolve_local_uri(gltf, "sub/a.bin"), canon + "/sub/a.bin");
  EXPECT_EQ(resolved("sub/a.bin"), canon + "/sub/a.bin");
  EXPECT_EQ(resolved("sub/../sub/./a.bin"), canon + "/sub/a.bin");
  EXPECT_EQ(resolved("s%75b/a.bin"), canon + "/sub/a.bin");  // %75 is 'u'
  EXPECT_EQ(resolved("in/a.bin"), canon + "/sub/a.bin");
  EXPECT_EQ(resolved("in_abs/a.bin"), canon + "/sub/a.bin");
  EXPECT_EQ(resolved("missing.bin"), canon + "/missing.bin");  // the reader says it does not exist
  const std::pair<const char*, const char*> refused[] = {
      {"/etc/passwd", "is an absolute path"},
      {"../secret.bin", "leaves the glTF's folder"},
      {"../../../../etc/passwd", "leaves the glTF's folder"},
      {"..%2Fsecret.bin", "leaves the glTF's folder"},
      {"%2E%2E/secret.bin", "leaves the glTF's folder"},
      {"%2Fetc%2Fpasswd", "is an absolute path"},
      {"sub/../../secret.bin", "leaves the glTF's folder"},
      {"out/secret.bin", "leaves the glTF's folder"},
      {"out_abs.bin", "leaves the glTF's folder through a symbolic link"},
      {"loop", "more than 40 symbolic links"},
      // Below a missing component nothing is looked up, until ".." climbs back out of it.
      {"missing/../out_abs.bin", "leaves the glTF's folder through a symbolic link"},
      {"missing/x/../../out/secret.bin", "leaves the glTF's folder"},
      {"a%zz.bin", "malformed percent-encoding"},
      {"a%2", "malformed percent-encoding"},
      {"a%00.bin", "encodes a NUL byte"},
      {"", "is empty"},
  };
  // Found by fuzz_uri: a raw NUL byte ended the path given to lstat, so "..\0x" resolved as "..".
  EXPECT_NE(error_of([&] { resolved(std::string("..\0x", 4)); }).find("holds a NUL byte"), std::string::npos);
  for (const auto& [uri, why] : refused) {
    const std::string e = error_of([&] { resolved(uri); });
    EXPECT_NE(e.find(why), std::string::npos) << uri << ": " << e;
    EXPECT_EQ(e.rfind(std::string("URI '") + uri + "'", 0), 0u) << e;
  }
}

// Through the command, the Python-free readers and `lut --scene`: one line naming the glTF and the
// URI, exit 2, and the same words whether the file outside exists or not (no message tells).
TEST(Untrusted, AnEscapingUriIsRefusedAndSaysNothingAboutTheFileOutside) {
  const fs::path root = fresh("escape");
  write(root / "secret.bin", std::string(24, 's'));
  const fs::path scene = root / "scene";
  const std::string there = (scene / "there.gltf").string(), absent = (scene / "absent.gltf").string();
  write(there, asset("../secret.bin").dump());
  write(absent, asset("../no_such.bin").dump());
  const ToolRun a = run_dspbr("scene analyze " + there), b = run_dspbr("scene analyze " + absent);
  EXPECT_EQ(a.status, 2) << a.output;
  EXPECT_EQ(b.status, 2) << b.output;
  EXPECT_EQ(a.output, "dspbr: error: " + there + ": buffers[0]: URI '../secret.bin' leaves the glTF's folder\n");
  EXPECT_EQ(b.output, "dspbr: error: " + absent + ": buffers[0]: URI '../no_such.bin' leaves the glTF's folder\n");
  for (const std::string uri : {"/etc/passwd", "..%2F..%2F..%2Fetc%2Fpasswd"}) {
    const std::string path = (scene / "abs.gltf").string();
    write(path, asset(uri).dump());
    expect_usage_error("scene analyze " + path, path + ": buffers[0]: URI '" + uri + "'");
    expect_usage_error("lut --scene " + path + " --out " + (root / "out").string(), path + ": buffers[0]: URI");
    EXPECT_FALSE(fs::exists(root / "out"));
  }
  // Images too (they are never read, but their URIs are checked the same way).
  Json doc = asset("data:application/octet-stream;base64,AAECAwQFBgcICQoLDA0ODxAREhMUFRYX");
  doc["images"] = {{{"uri", "../secret.png"}}};
  write(scene / "image.gltf", doc.dump());
  expect_usage_error("scene analyze " + (scene / "image.gltf").string(), "images[0]: URI '../secret.png' leaves the glTF's folder");
  // A buffer inside the folder is read as before.
  write(scene / "geo.bin", std::string(24, 'g'));
  write(scene / "ok.gltf", asset("geo.bin").dump());
  const ToolRun ok = run_dspbr("scene analyze " + (scene / "ok.gltf").string());
  EXPECT_EQ(ok.status, 0) << ok.output;
}

// glTF 2.0 schema: counts at least 1 and within their views, indices within their arrays,
// extension members objects.
TEST(Untrusted, GltfFieldsAreCheckedAsTheSchemaSays) {
  const std::string data = "data:application/octet-stream;base64,AAECAwQFBgcICQoLDA0ODxAREhMUFRYX";
  const fs::path dir = fresh("fields");
  const std::string path = (dir / "f.gltf").string();
  auto error = [&](const Json& doc) {
    write(path, doc.dump());
    return error_of([&] { gltf::read_gltf(path); });
  };
  EXPECT_EQ(error(asset(data)), "(no error)");
  EXPECT_EQ(error(asset(data, 2)), "(no error)");  // 2 x 12 bytes: exactly the view
  const std::pair<Json, std::string> counts[] = {
      {-5, "accessors[0]: \"count\" must be a non-negative integer, got -5"},
      {0, "accessors[0]: \"count\" must be at least 1, got 0"},
      {3, "accessors[0]: 3 elements of 12 bytes from byteOffset 0 do not fit in bufferView 0 (24 bytes)"},
      {Json(std::uint64_t(18446744073709551615ull)), "accessors[0]: 18446744073709551615 elements of 12 bytes from byteOffset 0 do not fit in bufferView 0 (24 bytes)"},
      {1.5, "accessors[0]: \"count\" must be a non-negative integer, got 1.5"},
  };
  for (const auto& [count, why] : counts) EXPECT_EQ(error(asset(data, count)), path + ": " + why);
  Json doc = asset(data);
  doc["buffers"][0]["byteLength"] = 0;
  EXPECT_EQ(error(doc), path + ": buffers[0]: \"byteLength\" must be at least 1, got 0");
  doc = asset(data);
  doc["accessors"][0]["byteOffset"] = 16;  // 16 + 12 + 12 > 24
  EXPECT_NE(error(doc).find("do not fit in bufferView 0"), std::string::npos);
  doc = asset(data);
  doc["accessors"][0]["type"] = "VEC7";
  EXPECT_EQ(error(doc), path + ": accessors[0]: \"type\" \"VEC7\" is not a glTF accessor type");
  doc = asset(data);
  doc["meshes"][0]["primitives"][0]["material"] = 9;
  EXPECT_EQ(error(doc), path + ": meshes[0].primitives[0]: \"material\" refers to materials[9], which does not exist");
  doc = asset(data);
  doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 4;
  EXPECT_NE(error(doc).find("\"NORMAL\" refers to accessors[4], which does not exist"), std::string::npos);
  doc = asset(data);
  doc["nodes"] = {{{"children", {7}}}};
  EXPECT_NE(error(doc).find("nodes[0].children[0]: \"node\" refers to nodes[7]"), std::string::npos);
  doc = asset(data);
  doc["extensions"] = "KHR";
  EXPECT_EQ(error(doc), path + ": extensions must be an object, got \"KHR\"");
  doc = asset(data);
  doc["materials"][0]["extensions"] = {{"KHR_materials_sheen", 3}};
  EXPECT_EQ(error(doc), path + ": materials[0].extensions.KHR_materials_sheen must be an object, got 3");
  doc = asset(data);
  doc["materials"][0]["extras"] = {{"extensions", "anything"}};  // extras are the application's own
  EXPECT_EQ(error(doc), "(no error)");
}

// `scene analyze --json` refuses to print a value that overflows (emission 1e308 x 1e308) instead
// of writing null; a large finite value is printed.
TEST(Untrusted, SceneAnalysisWritesNoNonFiniteNumber) {
  const fs::path dir = fresh("nonfinite");
  Json doc = asset("data:application/octet-stream;base64,AAECAwQFBgcICQoLDA0ODxAREhMUFRYX");
  doc["materials"][0]["emissiveFactor"] = {1e308, 1e308, 1e308};
  doc["materials"][0]["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e308}}}};
  doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  const std::string path = (dir / "bright.gltf").string();
  write(path, doc.dump());
  const ToolRun r = run_dspbr("scene analyze --json --parameters " + path);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  // refused where it is read (before: when the JSON was written), naming the file and the material
  EXPECT_NE(r.output.find("bright.gltf: materials[0] 'm': emissiveFactor x KHR_materials_emissive_strength"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("null"), std::string::npos) << r.output;
  doc["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 1;
  write(path, doc.dump());
  const ToolRun ok = run_dspbr("scene analyze --json --parameters " + path);
  EXPECT_EQ(ok.status, 0) << ok.output;
  EXPECT_EQ(ok.output.find("null"), std::string::npos) << ok.output;
}

// Integers on the command line are decimal ("010" is ten, never octal eight), out-of-range ones
// are named with their option, and --samples 0 is refused instead of meaning the default.
TEST(Untrusted, CommandLineNumbersAreDecimal) {
  const fs::path dir = fresh("decimal");
  const std::string out = (dir / "t").string();
  const ToolRun r = run_dspbr("lut --quiet --seed 010 --integrator qmc --samples 64 --tables GGX_E --size GGX_E=4x4 --formats json --out " + out);
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream in(dir / "t" / "dspbr_luts.json");
  const Json j = Json::parse(in);
  EXPECT_EQ(j["seed"], 10) << j["seed"];
  const std::string base = "lut --tables GGX_E --size GGX_E=4x4 --formats json --out " + (dir / "refused").string();
  expect_usage_error(base + " --samples 0", "--samples: must be a sample count from 1 to 2147483647 (decimal digits), got '0'");
  expect_usage_error(base + " --samples 99999999999", "--samples: must be a sample count from 1 to 2147483647 (decimal digits), got '99999999999'");
  expect_usage_error(base + " --seed 0x10", "--seed: must be an integer from 0 to 18446744073709551615 (decimal digits), got '0x10'");
  expect_usage_error(base + " --threads 1e3", "--threads:");
  EXPECT_FALSE(fs::exists(dir / "refused"));
  // A parameter too small for a normal double is a number (subnormal or zero), one beyond the
  // range of a double is named.
  const ToolRun tiny = run_dspbr("eval --set attenuationDistance=1e-308 --set transparency=1 --view 0,0,1 --light 0,0,-1");
  EXPECT_EQ(tiny.status, 0) << tiny.output;
  expect_usage_error("eval --set roughness=1e999 --view 0,0,1 --light 0,0,1", "parameter 'roughness': '1e999' is beyond the range of a double");
  expect_usage_error("eval --set roughness=0x1p-2 --view 0,0,1 --light 0,0,1", "parameter 'roughness': '0x1p-2' is not a number");
  // Issue 45 (poor list): one number grammar for every real-valued option; an empty value or a
  // non-finite one is an error naming the option, never the default.
  expect_usage_error("eval --view 0x1p0,0,1 --light 0,0,1", "--view expects 3 comma-separated decimal numbers, got '0x1p0,0,1'");
  expect_usage_error("sample --view 0,0,1 --u 0.5,nan,0.5", "--u expects 3 comma-separated decimal numbers, got '0.5,nan,0.5'");
  const std::string grammar = ": must be a decimal number (as JSON writes numbers: 0.5, -2, 1e-7), got '";
  expect_usage_error("eval --view 0,0,1 --light 0,0,1 --wavelength 0x10", "--wavelength" + grammar + "0x10'");
  expect_usage_error("eval --view 0,0,1 --light 0,0,1 --wavelength ''", "--wavelength" + grammar + "'");
  expect_usage_error("eval --view 0,0,1 --light 0,0,1 --area inf", "--area" + grammar + "inf'");
  expect_usage_error(base + " --target-error nan", "--target-error" + grammar + "nan'");
  EXPECT_FALSE(fs::exists(dir / "refused"));
  // The results reader: a CSV number is decimal too.
  try {
    dspbr::conformance::parse_results("id,f_cos_r,f_cos_g,f_cos_b\na,0x10,0,0\n", "r.csv");
    ADD_FAILURE() << "0x10 read as a number";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("f_cos_r is not a finite decimal number: '0x10'"), std::string::npos) << e.what();
  }
}

// Issue 45 (poor list): a results file that starts with a UTF-8 byte-order mark is read as what
// follows it, JSON or CSV (a spreadsheet's export).
TEST(Untrusted, AByteOrderMarkIsSkipped) {
  const std::string bom = "\xEF\xBB\xBF";
  for (const std::string text : {bom + R"({"results": [{"id": "a", "f_cos": [1, 2, 3]}]})", bom + "id,f_cos_r,f_cos_g,f_cos_b\na,1,2,3\n"}) {
    const auto rs = dspbr::conformance::parse_results(text, "r");
    ASSERT_EQ(rs.size(), 1u) << text;
    EXPECT_EQ(rs[0].id, "a");
    EXPECT_EQ(rs[0].f_cos->b, 3.0);
  }
}

// The number grammar is JSON's: parse_decimal accepts exactly the texts nlohmann's JSON parser
// reads as one number, with the same value, and calls out of range what it calls an overflow;
// only the whitespace a JSON document may have around its value is not part of a number.
TEST(Untrusted, DecimalGrammarIsJsonNumbers) {
  const char* texts[] = {"0", "-0", "1", "-1", "10", "0.5", "-0.25", "1e-7", "1E+3", "2.5e-3", "123456789012345678901234567890",
                         "1e-320", "4.9e-324", "1e-400", "1.7976931348623157e308", "1e999", "-1e999", "", "-", "+1", ".5",
                         "5.", "01", "00", "-01", "1e", "1e+", "0x10", "0x1p0", "nan", "NaN", "inf", "-inf", "Infinity",
                         " 1", "1 ", "1,5", "1.5.5", "--1", "1e5e5", "\t1", "1_000", "١"};
  for (const char* t : texts) {
    const dspbr::Decimal d = dspbr::parse_decimal(t);
    bool number = false, overflow = false;
    double value = 0;
    const std::string text(t);
    const bool spaced = !text.empty() && (std::isspace((unsigned char)text.front()) || std::isspace((unsigned char)text.back()));
    try {
      const Json j = Json::parse(spaced ? "\"\"" : text);
      number = j.is_number();
      if (number) value = j.get<double>();
    } catch (const Json::out_of_range&) {
      overflow = true;  // nlohmann: "number overflow parsing"
    } catch (const Json::exception&) {
    }
    if (overflow) {
      EXPECT_EQ(d.status, dspbr::Decimal::OutOfRange) << t;
    } else if (number) {
      EXPECT_EQ(d.status, dspbr::Decimal::Ok) << t;
      EXPECT_EQ(d.value, value) << t;
    } else {
      EXPECT_EQ(d.status, dspbr::Decimal::NotANumber) << t;
    }
  }
}

// A refused validate (its table file malformed) leaves no output folder behind.
TEST(Untrusted, ARefusedValidateLeavesNoFolder) {
  const fs::path dir = fresh("validate");
  const fs::path tables = fresh("validate_tables") / "tables.json";
  write(tables, R"({"format": "dspbr_luts", "version": 1, "tables": {}})");
  const std::string out = (dir / "a" / "report").string();
  const ToolRun r = run_dspbr("validate --quick --no-html --luts " + tables.string() + " --out " + out);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(tables.string()), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir)) << r.output;
}

// A file name with a newline or ESC stays on one line in the message (control characters escaped).
TEST(Untrusted, ControlCharactersInAFileNameAreEscaped) {
  const fs::path dir = fresh("names");
  const std::string name = (dir / "a\nb\x1b[31m.gltf").string();
  const ToolRun r = run_dspbr("scene analyze '" + name + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output, "dspbr: error: " + dir.string() + "/a\\x0ab\\x1b[31m.gltf does not exist\n");
}

// Names read from files reach the terminal escaped too (found by this stop's fresh tester: `params
// list`, `params show`, `params check` and `conformance check`'s summary printed them raw: ESC
// sequences, forged lines).
TEST(Untrusted, ControlCharactersInNamesFromFilesAreEscaped) {
  const fs::path dir = fresh("names_in_files");
  const std::string evil = "e\\u001b[31mvil\\nforged";  // JSON text: ESC and a newline
  const fs::path params = dir / "params.json";
  write(params, R"({"materials": {")" + evil + R"(": {"name": ")" + evil +
                    R"(", "parameters": {"roughness": {"type": "float", "default": 0.5}}}}})");
  const fs::path instance = dir / "instance.json";
  write(instance, R"({"material": ")" + evil + R"(", "values": {}})");
  for (const std::string& cmd : {"params list " + params.string(), "params show " + params.string() + " \"$(printf 'e\\033[31mvil\\nforged')\"",
                                 "params check --params " + params.string() + " " + instance.string()}) {
    const ToolRun r = run_dspbr(cmd);
    EXPECT_EQ(r.status, 0) << cmd << ": " << r.output;
    EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << cmd << ": " << r.output;
    EXPECT_NE(r.output.find("e\\x1b[31mvil\\x0aforged"), std::string::npos) << cmd << ": " << r.output;
  }
  // A NUL byte no longer ends the message early (it ended "unknown material 'generic").
  const fs::path nul = dir / "nul.json";
  write(nul, R"({"material": "generic\u0000x", "values": {"x\u0000y": 1}})");
  const ToolRun e = run_dspbr("eval --view 0,0,1 --light 0,0,1 --material " + nul.string());
  EXPECT_EQ(e.status, 2) << e.output;
  EXPECT_NE(e.output.find("unknown material 'generic\\x00x' (built-in"), std::string::npos) << e.output;
  write(nul, R"({"material": "generic", "values": {"x\u0000y": 1}})");
  const ToolRun c = run_dspbr("params check " + nul.string());
  EXPECT_NE(c.output.find("unknown parameter 'x\\x00y' for material 'generic'"), std::string::npos) << c.output;
}

// An empty list option is refused like the other list options (found by this stop's fresh tester:
// `fit --only ""` ran every fit, `eval --components ""` used the material's components).
TEST(Untrusted, EmptyListsAreRefused) {
  const fs::path dir = fresh("empty_lists");
  for (const std::string& cmd : {"fit --quick --only '' --out " + (dir / "f").string(),
                                 std::string("eval --view 0,0,1 --light 0,0,1 --components ''")}) {
    const ToolRun r = run_dspbr(cmd);
    EXPECT_EQ(r.status, 2) << cmd << ": " << r.output;
    EXPECT_NE(r.output.find(": must name at least one, got ''"), std::string::npos) << cmd << ": " << r.output;
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

// `fit --only` keeps the other fits' documents of --out: a malformed one is bad input (exit 2),
// named before any fit runs, and the folder stays as it was (the tenth fresh tester's pass: exit 1,
// after the whole fit).
TEST(Untrusted, FitOnlyReadsTheKeptDocumentsFirst) {
  // Malformed, not an object, another fit's document, a coefficient beyond float (the eleventh
  // fresh tester's pass: rc 1 and nlohmann's raw text after the fit), a dangling link.
  const std::string committed = read_all(fs::path(DSPBR_SOURCE_DIR) / "fits" / "flake_roughness.json");
  const std::pair<std::string, std::string> cases[] = {
      {"{\"bad\": ", "albedo.json: malformed JSON"},
      {"null", "albedo.json: not the albedo fit's document (not a JSON object)"},
      {"{}", "albedo.json: not the albedo fit's document: no /coefficients/ggx_E"},
      {committed, "albedo.json: not the albedo fit's document: no /coefficients/ggx_E"}};
  int k = 0;
  for (const auto& [content, message] : cases) {
    const fs::path dir = fresh("fit_only_kept_" + std::to_string(k++));
    write(dir / "albedo.json", content);
    const ToolRun r = run_dspbr("fit --quick --only flake_roughness --threads 1 --out " + dir.string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("flake_roughness:"), std::string::npos) << "the fit ran first: " << r.output;
    std::size_t entries = 0;
    for (const auto& e : fs::directory_iterator(dir)) entries += e.path().filename() == "albedo.json" ? 0 : 1;
    EXPECT_EQ(entries, 0u);
  }
  const fs::path dir = fresh("fit_only_kept_huge");
  write(dir / "flake_roughness.json", std::regex_replace(committed, std::regex("\"coefficients\": \\[\\s*[-0-9.e+]+"),
                                                          "\"coefficients\": [1e300"));
  const ToolRun r = run_dspbr("fit --quick --only sheen_lambda --threads 1 --out " + dir.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("/coefficients/0 is not a number within the float range"), std::string::npos) << r.output;
}

// A scene whose materials need no table: `lut --scene` says so naming the scene, exit 0, writes
// nothing (as `shader --scene`; it was "no tables selected", exit 2: the tenth fresh tester's pass).
TEST(Untrusted, LutForASceneWithoutMaterials) {
  const fs::path dir = fresh("lut_no_materials");
  write(dir / "none.gltf", R"({"asset": {"version": "2.0"}, "materials": []})");
  const ToolRun r = run_dspbr("lut --scene " + (dir / "none.gltf").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("none.gltf: its materials need no tables; nothing written"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// A material instance file has one size limit whichever command reads it: --scene refuses what
// eval --material refuses (the tenth fresh tester's pass: a 19 MB instance passed --scene).
TEST(Untrusted, AMaterialInstanceHasOneSizeLimit) {
  const fs::path dir = fresh("instance_limit");
  const std::string instance = R"({"material": "generic", "values": {"roughness": 0.3}})";
  write(dir / "big.json", instance.substr(0, instance.size() - 1) + std::string(17 << 20, ' ') + "}");
  const std::string file = (dir / "big.json").string();
  for (const std::string& cmd : {"eval --view 0,0,1 --light 0,0,1 --material " + file,
                                 "lut --scene " + file + " --out " + (dir / "l").string(),
                                 "shader --scene " + file + " --out " + (dir / "s").string()}) {
    const ToolRun r = run_dspbr(cmd);
    EXPECT_EQ(r.status, 2) << cmd << ": " << r.output;
    EXPECT_NE(r.output.find("big.json is 17.0 MB, larger than the limit of 16.0 MB"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "l") || fs::exists(dir / "s"));
}

// eval and sample take each parameter once: a second --set of the same one is an error naming
// both (the eleventh fresh tester's pass: the last value was taken silently); different ones pass.
TEST(Untrusted, EachParameterIsSetOnce) {
  for (const char* cmd : {"eval --light 0,0,1", "sample --u 0.5,0.5,0.5"}) {
    const ToolRun twice = run_dspbr(std::string(cmd) + " --view 0,0,1 --set roughness=0.3 --set metallic=1 --set roughness=0.5");
    EXPECT_EQ(twice.status, 2) << twice.output;
    EXPECT_EQ(twice.output, "dspbr: error: --set roughness=0.5: roughness is already set by --set roughness=0.3; give "
                            "each parameter once\n");
    const ToolRun once = run_dspbr(std::string(cmd) + " --view 0,0,1 --set roughness=0.3 --set metallic=1");
    EXPECT_EQ(once.status, 0) << once.output;
  }
}

// A stray comma in a list option is refused, whole value quoted (found by the third fresh tester's
// pass: eval/shader --components, fit --only and check --groups/--components took "a," as "a").
TEST(Untrusted, StrayCommasInListsAreRefused) {
  const fs::path dir = fresh("stray_commas");
  write(dir / "v.json", "{}");
  const std::string check = "conformance check " + (dir / "v.json").string() + " " + (dir / "v.json").string() +
                            " --out " + (dir / "r").string();
  const std::pair<std::string, std::string> cases[] = {
      {"fit --quick --only albedo, --out " + (dir / "f").string(), "--only: has an empty item (a stray comma) in 'albedo,'"},
      {"eval --view 0,0,1 --light 0,0,1 --components ,metallic", "--components: has an empty item (a stray comma) in ',metallic'"},
      {"shader --components metallic,,sheen --out " + (dir / "s").string(),
       "--components: has an empty item (a stray comma) in 'metallic,,sheen'"},
      {check + " --groups sheen,", "--groups: has an empty item (a stray comma) in 'sheen,'"},
      {check + " --components sheen,", "--components: has an empty item (a stray comma) in 'sheen,'"},
      {"conformance run --glsl " + (dir / "v.json").string() + " --out " + (dir / "r").string() + " --groups ,sheen",
       "--groups: has an empty item (a stray comma) in ',sheen'"}};
  for (const auto& [cmd, message] : cases) {
    const ToolRun r = run_dspbr(cmd);
    EXPECT_EQ(r.status, 2) << cmd << ": " << r.output;
    EXPECT_EQ(r.output, "dspbr: error: " + message + "\n") << cmd;
  }
  fs::remove(dir / "v.json");
  EXPECT_TRUE(fs::is_empty(dir));
}

// Options a layout would ignore are refused (found by the third fresh tester's pass: `lut --layout
// renderer` wrote its fixed set whatever --tables/--size/--grid/--scene said, --renderer-scale
// without the renderer layout and --half with --formats json changed nothing).
TEST(Untrusted, LutOptionsALayoutWouldIgnoreAreRefused) {
  const fs::path dir = fresh("lut_ignored");
  const std::string out = " --out " + (dir / "o").string();
  const std::pair<std::string, std::string> cases[] = {
      {"lut --layout renderer --tables GGX_E", "--tables applies to the published tables only"},
      {"lut --layout published,renderer --size GGX_E=8x8", "--size applies to the published tables only"},
      {"lut --layout renderer --grid endpoint", "--grid applies to the published tables only"},
      {"lut --tables GGX_E --renderer-scale 2", "--renderer-scale sets the renderer layout's resolution"},
      {"lut --formats json --half", "--half writes EXRs as 16-bit floats"}};
  for (const auto& [cmd, message] : cases) {
    const ToolRun r = run_dspbr(cmd + out);
    EXPECT_EQ(r.status, 2) << cmd << ": " << r.output;
    EXPECT_EQ(r.output.rfind("dspbr: error: " + message, 0), 0u) << cmd << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << cmd << ": " << r.output;
  }
  EXPECT_TRUE(fs::is_empty(dir));
  // --grid alone selects the published layout, as --tables does (the renderer set is not written).
  const ToolRun g = run_dspbr("lut --quiet --grid endpoint --tables GGX_E_avg --size GGX_E_avg=3 --formats json" + out);
  EXPECT_EQ(g.status, 0) << g.output;
  EXPECT_TRUE(fs::exists(dir / "o" / "dspbr_luts.json"));
  EXPECT_FALSE(fs::exists(dir / "o" / "dspbr_renderer_luts.json"));
}

// Messages that said something else than what happened (the third fresh tester's pass): a folder
// given to validate --luts ("File is actually a directory"), an empty file name ("' does not
// exist"), a folder reference cannot write in (exit 1 after the work), a stdout that failed
// during the command ("Input/output error" for a full disk).
TEST(Untrusted, MessagesSayWhatHappened) {
  const fs::path dir = fresh("messages");
  fs::create_directory(dir / "tables.json");
  const ToolRun luts = run_dspbr("validate --quick --luts " + (dir / "tables.json").string() + " --out " + (dir / "r").string());
  EXPECT_EQ(luts.status, 2);
  EXPECT_EQ(luts.output, "dspbr: error: --luts: " + (dir / "tables.json").string() + " is a directory\n");
  const ToolRun empty = run_dspbr("params check ''");
  EXPECT_NE(empty.output.find("'': an empty file name names no file"), std::string::npos) << empty.output;
  // sysfs refuses new files even to root (access() says yes): refused before the work, exit 2.
  if (fs::is_directory("/sys/kernel")) {
    const ToolRun sys = run_dspbr("conformance reference " + (dir / "v.json").string() + " --out /sys/kernel/r.json");
    EXPECT_EQ(sys.status, 2) << sys.output;
    EXPECT_EQ(sys.output.rfind("dspbr: error: --out: cannot write in the folder '/sys/kernel' (", 0), 0u) << sys.output;
  }
  const std::string cmd = std::string("\"") + DSPBR_EXE + "\" lut --bench-lookups --bench-points 10 > /dev/full 2> '" +
                          (dir / "err.txt").string() + "'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string err = read_all(dir / "err.txt");
  EXPECT_TRUE(err == "dspbr: error: cannot write the output to stdout: No space left on device\n" ||
              err == "dspbr: error: cannot write the output to stdout (a write failed; the output is incomplete)\n")
      << err;
  fs::remove(dir / "err.txt");
  fs::remove(dir / "tables.json");
  EXPECT_TRUE(fs::is_empty(dir));
}

// A run without HTML into a folder with an earlier run's pages replaces each page by one that gives
// this run's verdict (found by the fourth fresh tester's pass: check --no-html left an earlier
// PASS page beside a FAIL report.json; validate --no-html likewise index.html and report.html).
TEST(Untrusted, ARunWithoutHtmlLeavesNoEarlierVerdict) {
  const fs::path dir = fresh("earlier_pages");
  const fs::path v = dir / "v", rep = dir / "rep";
  ASSERT_EQ(run_dspbr("conformance generate --no-albedo --no-scenes --directions 1 --out " + v.string()).status, 0);
  write(dir / "zero.csv", "id,f_cos_r,f_cos_g,f_cos_b\nplain_metal/gold-r10/00,1,1,1\n");
  write(rep / "index.html", "<p>DSPBR conformance: PASS</p>");
  write(rep / "plots" / "old.png", "png");
  const ToolRun r = run_dspbr("conformance check " + (v / "vectors.json").string() + " " + (dir / "zero.csv").string() +
                              " --no-html --out " + rep.string());
  EXPECT_EQ(r.status, 1) << r.output;
  const std::string page = read_all(rep / "index.html");
  EXPECT_NE(page.find("its verdict is <b>FAIL</b>"), std::string::npos) << page;
  EXPECT_EQ(page.find("PASS"), std::string::npos) << page;
  EXPECT_TRUE(fs::exists(rep / "plots" / "old.png"));  // an earlier run's file: not deleted
  // A folder without pages gets none.
  const ToolRun fresh_run = run_dspbr("conformance check " + (v / "vectors.json").string() + " " +
                                      (dir / "zero.csv").string() + " --no-html --out " + (dir / "new").string());
  EXPECT_EQ(fresh_run.status, 1) << fresh_run.output;
  EXPECT_FALSE(fs::exists(dir / "new" / "index.html"));
}

// A lut run into a folder with an earlier table set it would not wholly replace is refused, and
// the folder keeps the earlier set (found by the fourth fresh tester's pass: a 4x4 json-only run
// left the 16x16 EXR and pbrlut.hpp beside its dspbr_luts.json).
TEST(Untrusted, ALutRunDoesNotMixTwoTableSets) {
  const fs::path dir = fresh("lut_mix");
  const std::string out = " --quiet --out " + (dir / "lc").string();
  ASSERT_EQ(run_dspbr("lut --tables GGX_E_avg --size GGX_E_avg=4 --formats json,hpp" + out).status, 0);
  const std::string json = read_all(dir / "lc" / "dspbr_luts.json"), hpp = read_all(dir / "lc" / "pbrlut.hpp");
  const ToolRun r = run_dspbr("lut --tables GGX_E_avg --size GGX_E_avg=3 --formats json" + out);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("holds files of an earlier table set that this run does not replace (pbrlut.hpp)"),
            std::string::npos) << r.output;
  EXPECT_EQ(read_all(dir / "lc" / "dspbr_luts.json"), json);
  EXPECT_EQ(read_all(dir / "lc" / "pbrlut.hpp"), hpp);
  EXPECT_EQ(listing(dir / "lc"), (std::set<std::string>{"dspbr_luts.json", "pbrlut.hpp"}));
  // The same set again replaces it.
  EXPECT_EQ(run_dspbr("lut --tables GGX_E_avg --size GGX_E_avg=3 --formats json,hpp" + out).status, 0);
  EXPECT_NE(read_all(dir / "lc" / "dspbr_luts.json"), json);
}

// A shader's own #include lines are read by the kit: regular files inside the shader's folder only
// (found by the fifth fresh tester's pass: the compiler opened an included FIFO and hung, and
// "../" reached any file). Refused in one line before anything is compiled or written.
TEST(Untrusted, ShaderIncludesStayInsideTheShadersFolder) {
  const fs::path dir = fresh("shader_includes");
  ASSERT_EQ(run_dspbr("conformance generate --no-albedo --no-scenes --directions 1 --out " + (dir / "v").string()).status, 0);
  const std::string body = "void conformance_eval(DspbrConformanceInput x, inout DspbrConformanceResult y) { }\n";
  fs::create_directories(dir / "sh");
  ASSERT_EQ(::mkfifo((dir / "sh" / "fifo").c_str(), 0600), 0);
  write(dir / "secret.glsl", body);
  write(dir / "sh" / "fifo.glsl", "#include \"fifo\"\n" + body);
  write(dir / "sh" / "up.glsl", "// a comment\n#include \"../secret.glsl\"\n");
  write(dir / "sh" / "cycle.glsl", "#include \"cycle.glsl\"\n");
  const std::pair<std::string, std::string> cases[] = {
      {"fifo.glsl", "fifo.glsl:1: #include: " + (dir / "sh" / "fifo").string() + " is not a regular file (a FIFO)"},
      {"up.glsl", "up.glsl:2: #include \"../secret.glsl\" leaves the folder of --glsl's file"},
      {"cycle.glsl", "nested more than 16 levels deep"}};
  for (const auto& [file, message] : cases) {
    const ToolRun r = run_dspbr("conformance run " + (dir / "v" / "vectors.json").string() + " --glsl " +
                                (dir / "sh" / file).string() + " --no-html --out " + (dir / "r").string());
    if (r.output.find("built without Vulkan") != std::string::npos) GTEST_SKIP() << r.output;
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(dir / "r")) << file;
  }
}

// Same command, same seed: the same image bytes (found by the fifth fresh tester's pass: OpenImageIO
// stamped each EXR with the time of writing).
TEST(Untrusted, ValidateImagesAreTheSameBytes) {
  const fs::path dir = fresh("validate_bytes");
  for (const char* run : {"a", "b"}) {
    const ToolRun r = run_dspbr("validate --quick --no-html --threads 1 --out " + (dir / run).string());
    ASSERT_EQ(r.status, 0) << r.output;
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // another second on the clock
  }
  std::size_t images = 0;
  for (const auto& e : fs::directory_iterator(dir / "a" / "images")) {
    EXPECT_EQ(read_all(e.path()), read_all(dir / "b" / "images" / e.path().filename())) << e.path().filename();
    ++images;
  }
  EXPECT_GT(images, 0u);
}

// Output that cannot be written is an error, not a success with nothing printed (found by this
// stop's second fresh tester: on a full disk `eval`, `scene analyze --json`, `params list` and
// `--help-all` exited 0 with an empty file). /dev/full fails every write with ENOSPC.
TEST(Untrusted, AnUnwritableStdoutIsAnError) {
  const fs::path dir = fresh("stdout");
  for (const std::string args : {"eval --view 0,0,1 --light 0,0,1", "params list", "--help-all", "--version",
                                 "conformance generate --help"}) {
    const fs::path err = dir / "err.txt";
    const std::string cmd = std::string("\"") + DSPBR_EXE + "\" " + args + " > /dev/full 2> '" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << args;
    EXPECT_EQ(WEXITSTATUS(status), 1) << args;
    EXPECT_EQ(read_all(err), "dspbr: error: cannot write the output to stdout: No space left on device\n") << args;
  }
}

// The quad integrator's tolerance has a floor (found by this stop's second fresh tester: at
// --target-error 1e-12 one cell of GGX_E_avg ran for hours, --samples bounding nothing).
TEST(Untrusted, AQuadToleranceBelowItsFloorIsRefused) {
  const fs::path dir = fresh("quad_floor");
  const ToolRun r = run_dspbr("lut --quiet --formats json --tables GGX_E_avg --size GGX_E_avg=1 --target-error 1e-12 --out " +
                              (dir / "o").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output, "dspbr: error: target error of the quad integrator must be 0 (its default) or at least 1e-10, got "
                      "1e-12 (below it rounding keeps the error estimate from converging)\n");
  EXPECT_TRUE(fs::is_empty(dir));
  // qmc's target is a standard error bounded by --samples: no floor there.
  const ToolRun q = run_dspbr("lut --quiet --formats json --tables GGX_E_avg --size GGX_E_avg=1 --integrator qmc "
                              "--samples 64 --target-error 1e-12 --out " + (dir / "q").string());
  EXPECT_EQ(q.status, 0) << q.output;
}

// Found by this stop's second fresh tester: a trailing comma was accepted in a vector option, and
// two options that need another were ignored without a word (after 26 s of table generation).
TEST(Untrusted, TrailingCommasAndOptionsWithoutTheirPartnerAreRefused) {
  const fs::path dir = fresh("partners");
  for (const std::string& cmd :
       {std::string("eval --view 0,0,1, --light 0,0,1"), std::string("sample --view 0,0,1 --u 0,0,0,"),
        "lut --bench-csv " + (dir / "x.csv").string() + " --out " + (dir / "o").string(),
        "lut --transmission-compensation --out " + (dir / "o").string()}) {
    const ToolRun r = run_dspbr(cmd);
    EXPECT_EQ(r.status, 2) << cmd << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << cmd << ": " << r.output;
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

// scene analyze FOLDER reads every .gltf and .glb entry: a FIFO named a.gltf is refused by the
// reader (found by this stop's second fresh tester: skipped without a word, while conformance
// generate --scenes refused it).
// A scene folder's .GLTF (a file from a case-insensitive file system) is a glTF file: scene
// analyze and conformance generate --scenes read it (both skipped it without a word; the sixth
// fresh tester's pass).
TEST(Untrusted, SceneFilesWithUpperCaseExtensionsAreRead) {
  const fs::path dir = fresh("scene_upper");
  std::ofstream(dir / "X.GLTF") << R"({"asset": {"version": "2.0"}, "materials": [{"name": "m"}]})";
  const ToolRun analyze = run_dspbr("scene analyze " + dir.string());
  EXPECT_EQ(analyze.status, 0) << analyze.output;
  EXPECT_NE(analyze.output.find("X.GLTF: 1 material(s)"), std::string::npos) << analyze.output;
  const ToolRun gen = run_dspbr("conformance generate --no-albedo --directions 1 --scenes " + dir.string() + " --out " +
                                (dir / "vectors").string());
  ASSERT_EQ(gen.status, 0) << gen.output;
  std::ifstream f(dir / "vectors" / "vectors.json");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"scenes/X/00\""), std::string::npos);
}

// A scene file whose name holds a newline would make vector ids that break the CSV files' lines
// (the sixth fresh tester's pass): refused, naming the file.
TEST(Untrusted, SceneFileNamesWithControlCharactersAreRefused) {
  const fs::path dir = fresh("scene_newline");
  std::ofstream(dir / "a\nb.gltf") << R"({"asset": {"version": "2.0"}, "materials": [{"name": "m"}]})";
  const ToolRun r = run_dspbr("conformance generate --no-albedo --directions 1 --scenes " + dir.string() + " --out " +
                              (dir / "vectors").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output, "dspbr: error: --scenes: " + dir.string() +
                          "/a\\x0ab.gltf: the file name has a control character, which no vector id may hold: rename "
                          "the file\n");
  EXPECT_FALSE(fs::exists(dir / "vectors"));
}

// A scene emitter that a float implementation cannot represent: a colour channel below the
// smallest normal float, an emitted luminance beyond the largest (the eighth fresh tester's pass:
// the vectors expected 149.67 and 9.55e38 where the shader library, in float, could only give 0 and
// 3.4e38). Refused naming the file and material.
TEST(Untrusted, SceneEmittersBeyondTheFloatRangeAreRefused) {
  const std::pair<const char*, const char*> cases[] = {
      {R"("emissiveFactor": [1e-46, 0, 0], "extensions": {"3DS_materials_emission": {"emissionValue": 100,
           "emissionEnergyNormalization": true}})",
       "emissionColor has a channel of 1e-46, below the smallest normal float (1.2e-38)"},
      {R"("emissiveFactor": [1e-6, 1, 0], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 3e38},
           "3DS_materials_emission": {"emissionValue": 10, "emissionMode": "LUMINOUS_POWER"}})",
       "its emitted luminance 9.55e+38 cd/m^2 is beyond the largest float (3.4e38)"}};
  int k = 0;
  for (const auto& [material, message] : cases) {
    const fs::path dir = fresh("scene_emitter_" + std::to_string(k++));
    std::ofstream(dir / "e.gltf") << R"({"asset": {"version": "2.0"}, "materials": [{"name": "e", )" << material << "}]}";
    const ToolRun r = run_dspbr("conformance generate --no-albedo --directions 1 --scenes " + dir.string() + " --out " +
                                (dir / "vectors").string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_EQ(r.output, "dspbr: error: --scenes: " + (dir / "e.gltf").string() + ": materials[0] 'e': " + message +
                            (k == 1 ? ": a float implementation reads 0 or loses its precision\n" : "\n"));
  }
}

TEST(Untrusted, SceneFolderEntriesThatAreNotFilesAreRefused) {
  const fs::path dir = fresh("scene_fifo");
  ASSERT_EQ(::mkfifo((dir / "a.gltf").c_str(), 0600), 0);
  const ToolRun r = run_dspbr("scene analyze " + dir.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output, "dspbr: error: " + (dir / "a.gltf").string() + " is not a regular file (a FIFO)\n");
}
