// Hostile input (limits in src/dspbr/limits.h, stated in docs/limits.md): each class gives its
// one-line error and exit status 2, or, for legal input at the edge, the answer computed another
// way (the same direction written with small numbers).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "dspbr/conformance/results.h"
#include "dspbr/gltf/gltf_file.h"
#include "dspbr/gltf/gltf_material.h"
#include "dspbr/io/atomic_file.h"
#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"
#include "dspbr/lutgen/lut_io.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/params/param_defs.h"
#include "test_params_run.h"

namespace {

using Json = nlohmann::json;

std::string temp_file(const std::string& name, const std::string& content) {
  const std::string path = ::testing::TempDir() + "/hostile_" + name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}


// `n` arrays nested inside each other.
std::string nested(int n) { return std::string(std::size_t(n), '[') + std::string(std::size_t(n), ']'); }

// A GLB container (glTF 2.0, "GLB File Format Specification") holding `json` as its JSON chunk.
std::string glb(std::string json) {
  while (json.size() % 4) json += ' ';
  auto le32 = [](std::uint32_t v) {
    return std::string{char(v & 0xff), char((v >> 8) & 0xff), char((v >> 16) & 0xff), char((v >> 24) & 0xff)};
  };
  return le32(0x46546C67) + le32(2) + le32(std::uint32_t(20 + json.size())) + le32(std::uint32_t(json.size())) +
         le32(0x4E4F534A) + json;
}

const std::string kDeepMessage = "JSON nested deeper than " + std::to_string(dspbr::limits::kJsonDepth) + " levels";

}  // namespace

TEST(Hostile, JsonNested1e5DeepIsRefusedByEveryReader) {
  const std::string deep = nested(100000);
  const std::string out = " --out " + ::testing::TempDir() + "/hostile_out";
  const std::string params = temp_file("deep_params.json", R"({"materials": {"m": {"parameters": {"p": {"type": "float", "x": )" + deep + "}}}}}");
  expect_usage_error("params list " + params, params + ": " + kDeepMessage);
  const std::string instance = temp_file("deep_instance.json", R"({"material": "generic", "values": {"roughness": )" + deep + "}}");
  expect_usage_error("eval --material " + instance + " --view 0,0,1 --light 0,0,1", instance + ": " + kDeepMessage);
  const ToolRun check = run_dspbr("params check " + instance);
  EXPECT_EQ(check.status, 2) << check.output;
  EXPECT_EQ(count_lines_with(check.output, instance + ": " + kDeepMessage), 1) << check.output;
  const std::string gltf = R"({"asset": {"version": "2.0"}, "materials": [{"extras": )" + deep + "}]}";
  const std::string gltf_path = temp_file("deep.gltf", gltf), glb_path = temp_file("deep.glb", glb(gltf));
  expect_usage_error("scene analyze " + gltf_path, gltf_path + ": " + kDeepMessage);
  expect_usage_error("scene analyze " + glb_path, glb_path + ": " + kDeepMessage);
  expect_usage_error("lut --scene " + glb_path + out, glb_path + ": " + kDeepMessage);
  const std::string published = temp_file("deep_luts.json", R"({"format": "dspbr_luts", "version": 1, "tables": )" + deep + "}");
  const std::string renderer =
      temp_file("deep_renderer.json", R"({"format": "dspbr_renderer_luts", "tables": {"GGX_E": {"axes": )" + deep + "}}}");
  expect_usage_error("validate --quick --no-html --luts " + published + out, published + ": " + kDeepMessage);
  expect_usage_error("validate --quick --no-html --luts " + renderer + out, renderer + ": " + kDeepMessage);
  // Just inside the limit the nesting is legal JSON: the reader gets to the document's content.
  const std::string at_limit = temp_file("limit.gltf", R"({"asset": {"version": "2.0"}, "extras": )" +
                                                           nested(dspbr::limits::kJsonDepth - 1) + "}");
  const ToolRun ok = run_dspbr("scene analyze " + at_limit);
  EXPECT_EQ(ok.status, 0) << ok.output;
  // Brackets inside strings are text, not nesting.
  EXPECT_NO_THROW(dspbr::parse_json(R"({"s": ")" + std::string(1000, '[') + R"("})", "strings.json", "test"));
}

TEST(Hostile, TableAxisSizesWhoseProductWrapsAreRefused) {
  // 2^22 * 2^21 * 2^21 = 2^64 wraps to 0 cells in 64 bits: an empty "values" would match.
  Json axes = Json::array();
  const int sizes[] = {1 << 22, 1 << 21, 1 << 21};
  const char* names[] = {"f0", "roughness", "cos_theta"};
  for (int d = 0; d < 3; ++d) axes.push_back({{"name", names[d]}, {"size", sizes[d]}, {"lo", 0}, {"hi", 1}, {"grid", "cell"}});
  const Json doc = {{"format", "dspbr_luts"}, {"version", 1}, {"tables", {{"Base_E", {{"axes", axes}, {"values", Json::array()}}}}}};
  const std::string path = temp_file("wrap_luts.json", doc.dump());
  const std::string message = "tables.Base_E.axes[0].size must be an integer from 1 to " +
                              std::to_string(dspbr::limits::kTableAxisSize) + ", got 4194304";
  expect_usage_error("validate --quick --no-html --luts " + path + " --out " + ::testing::TempDir() + "/hostile_out", message);
  try {
    dspbr::read_lut_json(path);
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
  // Within the per-axis limit the product is bounded by limits::kTableCells.
  Json big = doc;
  for (auto& a : big["tables"]["Base_E"]["axes"]) a["size"] = 4096;
  try {
    dspbr::read_lut_json_text(big.dump(), "big.json");
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("tables.Base_E: more than 16777216 cells"), std::string::npos) << e.what();
  }
}

TEST(Hostile, EmptyTablesObjectDoesNotValidate) {
  const std::string path = temp_file("empty_tables.json", R"({"format": "dspbr_luts", "version": 1, "tables": {}})");
  expect_usage_error("validate --quick --no-html --luts " + path + " --out " + ::testing::TempDir() + "/hostile_out",
                     path);
  EXPECT_THROW(dspbr::read_lut_json(path), std::runtime_error);
}

TEST(Hostile, LongInheritanceChainIsRefused) {
  // 30000 materials, each inheriting from the previous one: resolving copies each material's
  // ancestors (quadratic memory) and `params list --json` prints every chain (quadratic output).
  Json mats = Json::object();
  mats["m0"] = {{"parameters", {{"p0", {{"type", "float"}}}}}};
  for (int i = 1; i < 30000; ++i)
    mats["m" + std::to_string(i)] = {{"inherits", "m" + std::to_string(i - 1)},
                                     {"parameters", {{"p" + std::to_string(i), {{"type", "float"}}}}}};
  const std::string path = temp_file("chain.json", Json{{"materials", mats}}.dump());
  const std::string message = "inheritance chain longer than " + std::to_string(dspbr::limits::kInheritanceDepth) + " materials";
  expect_usage_error("params list " + path, message);
  expect_usage_error("params list --json " + path, message);
  // A chain at the limit resolves: the last material has every parameter of its bases.
  Json ok = Json::object();
  ok["m0"] = {{"parameters", {{"p0", {{"type", "float"}}}}}};
  for (int i = 1; i < dspbr::limits::kInheritanceDepth; ++i)
    ok["m" + std::to_string(i)] = {{"inherits", "m" + std::to_string(i - 1)},
                                   {"parameters", {{"p" + std::to_string(i), {{"type", "float"}}}}}};
  const dspbr::ParamDefs defs = dspbr::ParamDefs::from_json(Json{{"materials", ok}}, "ok.json");
  const auto& last = defs.material("m" + std::to_string(dspbr::limits::kInheritanceDepth - 1));
  EXPECT_EQ(last.parameters.size(), std::size_t(dspbr::limits::kInheritanceDepth));
  EXPECT_EQ(last.inherits.size(), std::size_t(dspbr::limits::kInheritanceDepth - 1));
}

TEST(Hostile, DoublingReferencesAreRefused) {
  // a_i = [a_(i-1), a_(i-1)]: 3 KB that expand to 2^60 values.
  Json d = {{"a0", {1, 2}}};
  for (int i = 1; i < 60; ++i) {
    const Json ref = {{"$ref", "#/materials/d/a" + std::to_string(i - 1)}};
    d["a" + std::to_string(i)] = Json::array({ref, ref});
  }
  const Json doc = {{"materials", {{"d", d}, {"m", {{"parameters", {{"p", {{"type", "float"}}}}}}}}}};
  const std::string path = temp_file("refs.json", doc.dump());
  expect_usage_error("params list " + path, "more than " + std::to_string(dspbr::limits::kResolvedJsonValues) + " JSON values");
  // A reference to a reference to ... deeper than the limit.
  Json chain = {{"r0", 1.0}};
  for (int i = 1; i <= dspbr::limits::kRefDepth + 1; ++i) chain["r" + std::to_string(i)] = {{"$ref", "#/materials/c/r" + std::to_string(i - 1)}};
  const std::string chain_path = temp_file("ref_chain.json", Json{{"materials", {{"c", chain}}}}.dump());
  expect_usage_error("params list " + chain_path, "too deep \"$ref\" chain");
}

TEST(Hostile, ResolvedValuesAreCountedWhileMerging) {
  // Issue 45, finding 3: 40,000 materials inheriting one base of ~1000 values (2.6 MB like the
  // tester's file, 40 million values merged) were all built before the count refused them (4.8 GB,
  // 30 s). The count is taken as each material is merged: b holds 1006 values (the document, its
  // "parameters", "p", "type", "enum" and its 1000 strings, "default"), each m_k 1007 (b's and its
  // "inherits"), so the limit is crossed at the first k with 1006 + 1007 (k + 1) > limit.
  Json names = Json::array();
  for (int i = 0; i < 1000; ++i) names.push_back("a" + std::to_string(i));
  Json materials = {{"b", {{"parameters", {{"p", {{"type", "enum"}, {"enum", names}, {"default", "a0"}}}}}}}};
  for (int k = 0; k < 40000; ++k) {
    char id[16];
    std::snprintf(id, sizeof id, "m%05d", k);
    materials[id] = {{"inherits", "b"}};
  }
  const std::size_t limit = dspbr::limits::kResolvedJsonValues;
  const std::size_t k = (limit - 1006) / 1007;  // 1006 + 1007 (k + 1) > limit, k the smallest
  ASSERT_GT(1006 + 1007 * (k + 1), limit);
  ASSERT_LE(1006 + 1007 * k, limit);
  char crossing[16];
  std::snprintf(crossing, sizeof crossing, "m%05zu", k);
  try {
    dspbr::ParamDefs::from_json(Json{{"materials", materials}}, "many.json");
    ADD_FAILURE() << "40,000 merged materials were accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "many.json: more than " + std::to_string(limit) +
                                         " JSON values once inheritance is merged, at material '" + crossing +
                                         "' (bases copied into many materials)");
  }
}

TEST(Hostile, UiOrderOutsideIntIsRefused) {
  for (const char* order : {"1099511627776", "-1", "2147483648"}) {
    const std::string path = temp_file("uiorder.json", std::string(R"({"materials": {"m": {"parameters": {"p": {"type": "float", "uiOrder": )") +
                                                           order + "}}}}}");
    expect_usage_error("params show " + path + " m", std::string("\"uiOrder\" must be an integer from 0 to 2147483647, got ") + order);
  }
}

TEST(Hostile, NumberWhereAStringBelongsNamesTheFileAndThePath) {
  const std::string out = " --out " + ::testing::TempDir() + "/hostile_out";
  const std::string luts = temp_file(
      "name_number.json",
      R"({"format": "dspbr_luts", "version": 1, "tables": {"GGX_E_avg": {"axes": [{"name": 5, "size": 2, "lo": 0, "hi": 1, "grid": "cell"}], "values": [1, 1]}}})");
  expect_usage_error("validate --quick --no-html --luts " + luts + out, luts + "': tables.GGX_E_avg.axes[0].name must be a string, got 5");
  const std::string format = temp_file("format_number.json", R"({"format": 5, "tables": {}})");
  expect_usage_error("validate --quick --no-html --luts " + format + out, format + "': not a dspbr_luts file");
  const std::string gltf = temp_file("alpha_number.gltf", R"({"asset": {"version": "2.0"}, "materials": [{"alphaMode": 5}]})");
  expect_usage_error("scene analyze " + gltf, gltf + ": materials[0] 'material 0': alphaMode must be a string");
  const std::string instance = temp_file("material_number.json", R"({"material": 5})");
  expect_usage_error("eval --material " + instance + " --view 0,0,1 --light 0,0,1",
                     instance + ": \"material\" must be a string (the material type, e.g. \"glass\"), got 5");
}

TEST(Hostile, BufferViewWhoseEndWrapsIsRefused) {
  // byteOffset 2^64 - 2 plus byteLength 4 wraps to 2, inside the 4-byte buffer.
  const std::string path = temp_file(
      "wrap.gltf",
      R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 4, "uri": "data:application/octet-stream;base64,AAAAAA=="}],
          "bufferViews": [{"buffer": 0, "byteOffset": 18446744073709551614, "byteLength": 4}]})");
  expect_usage_error("scene analyze " + path, "bufferViews[0] (bytes 18446744073709551614..");
}

TEST(Hostile, LfsPointerWithNegativeSizeIsNotAPointer) {
  // std::stoull reads "-5" as 2^64 - 5: the pointer would announce an enormous buffer.
  temp_file("negative.bin", "version https://git-lfs.github.com/spec/v1\noid sha256:00\nsize -5\n");
  const std::string path = temp_file(
      "lfs.gltf",
      R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 100, "uri": "hostile_negative.bin"}], "bufferViews": [{"buffer": 0, "byteLength": 100}]})");
  expect_usage_error("scene analyze " + path, "buffers[0] declares 100 bytes but only 65 are available");
}

TEST(Hostile, HugeButFiniteDirectionsGiveTheSameAnswerAsSmallOnes) {
  // The same direction written with components near the double maximum and near the smallest
  // subnormal: its squared length overflows or underflows, its direction does not.
  // The result without its provenance (which holds the command line).
  auto result = [](const std::string& args) {
    const ToolRun r = run_dspbr(args);
    EXPECT_EQ(r.status, 0) << args << "\n" << r.output;
    Json j = Json::parse(r.output, nullptr, false);
    if (j.is_object()) j.erase("provenance");
    return j;
  };
  const Json unit = result("eval --view 1,1,1 --light 0,1,1");
  ASSERT_TRUE(unit.is_object());
  EXPECT_EQ(result("eval --view 1e308,1e308,1e308 --light 0,1e308,1e308"), unit);
  EXPECT_EQ(result("eval --view 1e-320,1e-320,1e-320 --light 0,1e-320,1e-320"), unit);
  expect_usage_error("eval --view 1e309,0,1 --light 0,0,1", "--view expects 3 comma-separated finite numbers");
}

TEST(Hostile, ResultsThatOverflowAreErrorsNotNull) {
  // Legal values (emissionValue and emissionColor have no maximum) whose product exceeds the
  // largest double: the emission would print as null.
  expect_usage_error("eval --set emissionValue=1e308 --set emissionColor=10,10,10 --view 0,0,1 --light 0,0,1",
                     "the result \"emission[0]\" is not finite");
  expect_usage_error("sample --set emissionValue=1e308 --set emissionColor=10,10,10 --view 0,0,1 --u 0.5,0.5,0.5",
                     "is not finite");
  // Large but representable: printed as numbers.
  const ToolRun r = run_dspbr("eval --set emissionValue=1e300 --view 0,0,1 --light 0,0,1");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_GT(Json::parse(r.output)["emission"][0].get<double>(), 1e299);
}

TEST(Hostile, TableAxisWithAnEmptyRangeIsRefused) {
  // A GGX_E_avg table over roughness in [lo, hi], refused with `message`.
  const auto expect_refused = [](const std::string& lo, const std::string& hi, const std::string& message) {
    const std::string text = R"({"format": "dspbr_luts", "version": 1, "tables": {"GGX_E_avg": {"axes": [{"name": "roughness", "size": 2, "lo": )" +
                             lo + R"(, "hi": )" + hi + R"(, "grid": "cell"}], "values": [1, 1]}}})";
    try {
      dspbr::read_lut_json_text(text, "range.json");
      ADD_FAILURE() << "accepted [" << lo << ", " << hi << "]";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "'range.json': tables.GGX_E_avg.axes[0]: " + message);
    }
  };
  // Found by fuzz_luts: lo == hi made the lookup's cell index 0/0 (UBSan: NaN converted to int).
  expect_refused("0.5", "0.5", "lo must be below hi");
  // Found by this stop's fresh tester: lo -1e308, hi 1e308 was read, and validate failed only at the
  // end on a NaN error figure.
  expect_refused("-1e308", "1e308", "hi - lo must be finite and at least 1e-9");
  expect_refused("0", "5e-324", "hi - lo must be finite and at least 1e-9");  // the second fresh tester's
}

// Issue 45 (#1): the JSON readers build the document with nlohmann's plain SAX parser (linear in
// the input) instead of the callback parser, which scanned an object's or array's earlier siblings
// whenever one closed (200,000 empty nodes of a 600 kB glTF: 17.6 s in `scene analyze`; a million:
// minutes). 400,000 sibling objects (about a minute before) are read, with the reader's checks
// still on the way (a duplicate key after them is named by its path).
TEST(Hostile, ManySiblingObjectsAreReadWithTheChecks) {
  std::string nodes = R"({"asset": {"version": "2.0"}, "nodes": [)";
  for (int i = 0; i < 400000; ++i) nodes += i ? ",{}" : "{}";
  const nlohmann::json doc = dspbr::parse_json(nodes + "]}", "nodes.gltf", "glTF file");
  EXPECT_EQ(doc["nodes"].size(), 400000u);
  std::string dup = nodes + R"(,{"a": 1, "a": 2}]})";
  try {
    dspbr::parse_json(dup, "dup.gltf", "glTF file");
    ADD_FAILURE() << "a duplicate key was read";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "dup.gltf: duplicate key \"a\" in nodes[400000]");
  }
}

// Issue 45 (#2): the memory of a parsed document is charged while it is read (limits.h:
// json_memory_budget, 10 x its size + 64 MiB; per value costs measured in docs/limits.md). Empty
// objects cost ~100 bytes each for 3 bytes of text: 5 million of them (15 MB, under the 16 MB
// results limit) are refused naming the file; 300,000 (0.9 MB) and a million numbers are read.
TEST(Hostile, JsonBeyondTheMemoryBoundIsRefused) {
  const auto list = [](std::size_t n, const char* item) {
    std::string s = R"({"results": [)";
    for (std::size_t i = 0; i < n; ++i) (s += i ? "," : "") += item;
    return s + "]}";
  };
  const std::string big = list(5000000, "{}");
  ASSERT_LT(big.size(), dspbr::limits::kDocumentBytes);
  try {
    dspbr::parse_json(big, "r.json", "results file");
    ADD_FAILURE() << "5 million objects were read";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "r.json: its JSON values would take more than " +
                                         std::to_string(dspbr::limits::json_memory_budget(big.size()) >> 20) +
                                         " MiB in memory, 10 x the file's size + 64 MiB (the readers' bound, docs/limits.md)");
  }
  EXPECT_EQ(dspbr::parse_json(list(300000, "{}"), "r.json", "results file")["results"].size(), 300000u);
  EXPECT_EQ(dspbr::parse_json(list(1000000, "0"), "r.json", "results file")["results"].size(), 1000000u);
}

// Issue 45 (#2): a CSV results file is charged against the same bound, each row twice its Result
// (the vector's growth) and its id, and a line is split into at most the header's fields. Rows of 8 bytes took ~44 x the file before (15 MB: 500 MB);
// 4 MB of them are now refused at the row that exceeds the bound, and 100,000 rows are read.
TEST(Hostile, CsvResultsBeyondTheMemoryBoundAreRefused) {
  const auto rows = [](std::size_t n) {
    std::string s = "id,f_cos_r,f_cos_g,f_cos_b\n";
    for (std::size_t i = 0; i < n; ++i) s += "a,0,0,0\n";
    return s;
  };
  const std::string big = rows(500000);
  try {
    dspbr::conformance::parse_results(big, "r.csv");
    ADD_FAILURE() << "500,000 rows were read";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("r.csv: line ", 0), 0u) << m;
    EXPECT_NE(m.find(": its results would take more than " +
                     std::to_string(dspbr::limits::json_memory_budget(big.size()) >> 20) + " MiB in memory"),
              std::string::npos)
        << m;
  }
  EXPECT_EQ(dspbr::conformance::parse_results(rows(100000), "r.csv").size(), 100000u);
  // One line of 4 million commas was 4 million strings (15 MB of them: 685 MB); now refused at the
  // fifth field.
  try {
    dspbr::conformance::parse_results("id,f_cos_r,f_cos_g,f_cos_b\n" + std::string(4000000, ','), "r.csv");
    ADD_FAILURE() << "a line of commas was read";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "r.csv: line 2: more than 4 fields, the header has 4");
  }
}

// A glTF's materials are limited (limits.h kSceneMaterials): an analysis costs up to ~11 kB per
// material and an empty one 3 bytes of glTF, so 65,536 of them (197 kB) took 723 MB in
// `scene analyze --json --parameters`. One more than the limit is refused naming the file; the
// limit itself is read.
TEST(Hostile, GltfMaterialsBeyondTheLimitAreRefused) {
  const auto gltf = [](std::size_t n) {
    std::string s = R"({"asset": {"version": "2.0"}, "materials": [)";
    for (std::size_t i = 0; i < n; ++i) s += i ? ",{}" : "{}";
    s += "]}";
    return dspbr::gltf::parse_gltf(std::vector<std::uint8_t>(s.begin(), s.end()), "m.gltf");
  };
  const std::size_t limit = dspbr::limits::kSceneMaterials;
  try {
    dspbr::gltf::map_materials(gltf(limit + 1));
    ADD_FAILURE() << "more materials than the limit were read";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "m.gltf: " + std::to_string(limit + 1) + " materials, more than the limit of " +
                                         std::to_string(limit) + " (docs/limits.md)");
  }
  EXPECT_EQ(dspbr::gltf::map_materials(gltf(limit)).size(), limit);
}

// Found by this stop's fresh tester: emissiveFactor 1e308 times emissiveStrength 1e308 (each
// legal) made emissionColor infinite; `scene analyze --parameters` printed it as null, exit 0.
TEST(Hostile, GltfEmissionBeyondTheLargestNumberIsRefused) {
  const std::string s =
      R"({"asset": {"version": "2.0"}, "materials": [{"name": "hot", "emissiveFactor": [1e308, 1e308, 1e308],)"
      R"( "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 1e308}}}]})";
  try {
    dspbr::gltf::map_materials(dspbr::gltf::parse_gltf(std::vector<std::uint8_t>(s.begin(), s.end()), "e.gltf"));
    ADD_FAILURE() << "an infinite emission was read";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "e.gltf: materials[0] 'hot': emissiveFactor x KHR_materials_emissive_strength.emissiveStrength is beyond the "
              "largest number");
  }
  const ToolRun run = run_dspbr("scene analyze --parameters " + temp_file("hot.gltf", s));
  EXPECT_EQ(run.status, 2) << run.output;
}

// An output path that names a FIFO, a device or a link to one is refused before anything is
// written and keeps its type (before: rename(2) replaced it by a regular file, /dev/full included
// when run as root); a link to a regular file is still replaced by the new file, not written through.
// A file of the set whose place in --out is taken by a folder or a FIFO is bad input, as an --out
// that is a file: exit 2, nothing written (the eleventh fresh tester's pass: exit 1).
TEST(Hostile, AFolderWhereAnOutputFileGoesIsBadInput) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "hostile_folder_in_the_way";
  fs::remove_all(dir);
  fs::create_directories(dir / "folder" / "dspbr_specialization.h");
  fs::create_directories(dir / "fifo");
  ASSERT_EQ(::mkfifo((dir / "fifo" / "dspbr_specialization.h").c_str(), 0600), 0);
  for (const char* sub : {"folder", "fifo"}) {
    const ToolRun run = run_dspbr("shader --components sheen --out " + (dir / sub).string());
    EXPECT_EQ(run.status, 2) << sub << ": " << run.output;
    EXPECT_NE(run.output.find((dir / sub / "dspbr_specialization.h").string()), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("nothing written"), std::string::npos) << run.output;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / sub), fs::directory_iterator()), 1) << sub;
  }
  EXPECT_TRUE(fs::is_directory(dir / "folder" / "dspbr_specialization.h"));
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(dir / "fifo" / "dspbr_specialization.h")));
  fs::remove_all(dir);
}

TEST(Hostile, OutputsNeverReplaceAFifoOrADevice) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "hostile_special_outputs";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path fifo = dir / "fifo", to_device = dir / "null", to_file = dir / "link", file = dir / "file";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink("/dev/null", to_device);
  std::ofstream(file) << "old";
  fs::create_symlink(file, to_file);
  for (const fs::path& p : {fifo, to_device}) {
    try {
      dspbr::write_text_atomically(p.string(), "new");
      ADD_FAILURE() << p << " was written";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "cannot write '" + p.string() +
                                           "': it exists and is not a regular file (a folder, FIFO, device, socket "
                                           "or a link to one); name a file path");
    }
  }
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(to_device)));
  EXPECT_TRUE(fs::is_character_file(fs::status("/dev/null")));
  dspbr::write_text_atomically(to_file.string(), "new");  // the link is replaced, its target untouched
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(to_file)));
  std::ifstream old(file);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(old), {}), "old");
  // A refused write leaves no folder it created (found by the second fresh tester: write_results
  // to 'newdir/' or 'a/b/c/' left the empty folders): a path ending in a slash is refused before
  // anything, a name too long for a file after the parents were made, which are removed again.
  for (const fs::path& p : {dir / "newdir/", dir / "a" / "b" / std::string(300, 'x')}) {
    EXPECT_THROW(dspbr::write_text_atomically(p.string(), "new"), std::runtime_error) << p;
    EXPECT_FALSE(fs::exists(dir / "newdir") || fs::exists(dir / "a")) << p;
  }
  // The CLI refuses it before any work, naming the option (exit 2).
  const ToolRun run = run_dspbr("conformance reference no-such-vectors.json --out " + fifo.string());
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--out: cannot write '" + fifo.string() + "': it exists and is not a regular file"),
            std::string::npos)
      << run.output;
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  fs::remove_all(dir);
}
