// Scene analysis: active DSPBR components and needed tables per material, for the shared
// validation scenes, hand-made textured glTF materials and material instances, plus the
// `dspbr scene analyze` CLI on good and bad inputs. Expected components follow from the scene
// parameters read from the files (e.g. metallicFactor strictly between 0 and 1 -> metal and
// dielectric), textured ranges are cross-checked by sampling texture values.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "dspbr/gltf/gltf_file.h"
#include "dspbr/params/material_params.h"
#include "dspbr/rng.h"
#include "dspbr/scene/components.h"
#include "dspbr/scene/scene_analysis.h"
#include "test_params_run.h"

using namespace dspbr;
using Json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

const std::string kScenes = DSPBR_REFERENCE_DIR "/scenes/sphere/";
const std::string kData = DSPBR_SOURCE_DIR "/tests/data/";

std::set<std::string> names(uint32_t mask) {
  const auto v = component_names(mask);
  return {v.begin(), v.end()};
}

const MaterialAnalysis& by_name(const SceneAnalysis& s, const std::string& name) {
  for (const auto& m : s.materials)
    if (m.name == name) return m;
  throw std::runtime_error("no material " + name);
}

}  // namespace

// Every shared scene: the components implied by the file's factors.
TEST(Scene, SharedScenesComponentsFollowTheirFactors) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(kScenes)) {
    if (e.path().extension() != ".gltf") continue;
    SCOPED_TRACE(e.path().string());
    std::ifstream in(e.path());
    const Json mat = Json::parse(in)["materials"][0];
    Json ext = mat.value("extras", Json::object());
    const Json extensions = mat.value("extensions", Json::object());
    for (const auto& [k, v] : extensions.items()) ext[k] = v;
    const double metallic = mat["pbrMetallicRoughness"]["metallicFactor"].get<double>();
    std::set<std::string> expected;
    if (metallic > 0) expected.insert("metallic");
    if (metallic < 1) expected.insert("opaque_dielectric");
    if (metallic < 1 && ext.contains("3DS_materials_translucency") &&
        ext["3DS_materials_translucency"]["translucencyFactor"].get<double>() > 0)
      expected.insert("translucency");
    if (ext.contains("KHR_materials_sheen")) {
      const auto c = ext["KHR_materials_sheen"]["sheenColorFactor"];
      if (c[0].get<double>() + c[1].get<double>() + c[2].get<double>() > 0) expected.insert("sheen");
    }
    if (ext.contains("KHR_materials_clearcoat") && ext["KHR_materials_clearcoat"]["clearcoatFactor"].get<double>() > 0)
      expected.insert("clearcoat");
    const SceneAnalysis s = analyze_scene(e.path().string());
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(names(s.materials[0].components), expected);
    // Tables: GGX_E/GGX_E_avg for any specular lobe, Base_* for the dielectric base, Sheen_E for sheen.
    std::vector<std::string> tables{"GGX_E", "GGX_E_avg"};
    if (expected.count("opaque_dielectric")) tables.insert(tables.end(), {"Base_E", "Base_E_avg"});
    if (expected.count("sheen")) tables.push_back("Sheen_E");
    EXPECT_EQ(s.materials[0].tables, tables);
    EXPECT_EQ(s.tables, tables);
    EXPECT_EQ(tables_for_scene(e.path().string()), tables);
    ++n;
  }
  EXPECT_GE(n, 70);
}

TEST(Scene, TexturedParametersCountAsPossiblyNonZero) {
  const SceneAnalysis s = analyze_scene(kData + "gltf/materials.gltf");
  ASSERT_EQ(s.materials.size(), 4u);  // three materials + glTF's default material
  // metallicFactor 1 but textured -> dielectric possible; transmission 1 textured -> opaque too;
  // a volume with finite attenuation and dispersion; emissive and clearcoat factors are 0, so their
  // textures cannot switch them on (glTF textures multiply factors).
  EXPECT_EQ(names(by_name(s, "textured_paint").components),
            (std::set<std::string>{"metallic", "opaque_dielectric", "volumetric_transparent", "volume_absorption",
                                   "dispersion"}));
  EXPECT_EQ(names(by_name(s, "everything").components),
            (std::set<std::string>{"opaque_dielectric", "translucency", "thin_film", "sheen", "emission"}));
  EXPECT_EQ(by_name(s, "everything").tables,
            (std::vector<std::string>{"GGX_E", "GGX_E_avg", "Base_E", "Base_E_avg", "Sheen_E"}));
  EXPECT_EQ(names(by_name(s, "ds_emitter").components), (std::set<std::string>{"opaque_dielectric", "emission"}));
  EXPECT_EQ(names(by_name(s, "(default material)").components), (std::set<std::string>{"metallic"}));
  EXPECT_EQ(s.tables, (std::vector<std::string>{"GGX_E", "GGX_E_avg", "Base_E", "Base_E_avg", "Sheen_E"}));
}

// The corner rule of active_components(m, textured) against random texture values in [0, 1]:
// sampling never finds a component the corners miss, and finds every one they report.
TEST(Scene, TexturedCornersMatchSampledTextures) {
  Material m;
  m.metallic = 1.0;      // untextured: metal only
  m.transparency = 1.0;
  m.translucency = 0.5;
  m.thinWalled = false;
  m.sheenColor = Rgb(0.2, 0.3, 0.4);
  m.attenuationDistance = 1.0;
  m.attenuationColor = Rgb(0.5);
  m.subsurfaceColor = Rgb(0.2);
  m.abbeNumber = 30;
  const std::vector<std::string> textured{"metallic", "transparency", "translucency", "sheenColor", "subsurfaceColor"};
  const uint32_t corners = active_components(m, textured);
  uint32_t sampled = 0;
  Pcg32 rng(7, 0);
  for (int i = 0; i < 4000; ++i) {
    Material s = m;
    for (const auto& id : textured) {
      // Texture value: an end point 0 or 1 a third of the time each, else uniform.
      const double u = rng.next_double(), t = u < 1.0 / 3 ? 0.0 : (u < 2.0 / 3 ? 1.0 : rng.next_double());
      const Json v = get_material_parameter(m, id);
      set_material_parameter(s, id, v.is_array() ? Json::array({v[0].get<double>() * t, v[1].get<double>() * t,
                                                                v[2].get<double>() * t})
                                                 : Json(v.get<double>() * t));
    }
    sampled |= active_components(s);
  }
  EXPECT_EQ(sampled, corners);
  EXPECT_NE(corners, active_components(m));  // the textures do widen the set here
}

TEST(Scene, MaterialInstanceAsScene) {
  const SceneAnalysis s = analyze_scene(kData + "params/glass_ok.json");
  ASSERT_EQ(s.materials.size(), 1u);
  // glass: transparency 1 (hidden default), thinWalled false, attenuationDistance infinite.
  EXPECT_EQ(names(s.materials[0].components), (std::set<std::string>{"volumetric_transparent"}));
  EXPECT_EQ(s.tables, (std::vector<std::string>{"GGX_E", "GGX_E_avg"}));
  EXPECT_THROW(analyze_scene(kData + "params/bad_values.json"), std::runtime_error);
}

TEST(SceneCli, AnalyzeJsonAndBadInputs) {
  const auto r = run_dspbr("scene analyze " + kData + "gltf/materials.gltf --json");
  ASSERT_EQ(r.status, 0) << r.output;
  const Json j = Json::parse(r.output);
  ASSERT_EQ(j["materials"].size(), 4u);
  for (const auto& m : j["materials"]) {
    EXPECT_TRUE(m["name"].is_string());
    EXPECT_TRUE(m["components"].is_array());
    EXPECT_TRUE(m["tables"].is_array());
  }
  EXPECT_EQ(j["materials"][1]["name"], "everything");
  EXPECT_EQ(j["materials"][1]["components"],
            Json::array({"opaque_dielectric", "translucency", "thin_film", "sheen", "emission"}));
  // --parameters: the mapped values, checked against the file.
  const auto p = run_dspbr("scene analyze " + kScenes + "13-clearcoat-0.3.gltf --json --parameters");
  ASSERT_EQ(p.status, 0) << p.output;
  std::ifstream in(kScenes + "13-clearcoat-0.3.gltf");
  const Json scene = Json::parse(in);
  EXPECT_EQ(Json::parse(p.output)["materials"][0]["parameters"]["clearcoat"],
            scene["materials"][0]["extensions"]["KHR_materials_clearcoat"]["clearcoatFactor"]);
  EXPECT_EQ(run_dspbr("scene analyze " + kScenes + "09-sheen-metal.gltf").status, 0);

  // Bad inputs: one error line naming the file, exit status 2.
  std::vector<std::string> bad;
  for (const char* f : {"missing_buffer.gltf", "short_buffer.gltf", "wrong_types.gltf", "malformed.gltf", "bad_texture.gltf"})
    bad.push_back(kData + "gltf/" + f);
  bad.push_back(kData + "params/unknown_material.json");
  bad.push_back(kData + "does_not_exist.glb");
  // A truncated .glb: the first 40 bytes of a valid header + JSON chunk.
  const std::string glb = testing::TempDir() + "dspbr_truncated.glb";
  {
    std::ifstream src(kData + "gltf/materials.gltf");
    std::string json((std::istreambuf_iterator<char>(src)), std::istreambuf_iterator<char>());
    while (json.size() % 4) json += ' ';
    std::string bytes = "glTF";
    auto u32 = [&](uint32_t v) {
      for (int i = 0; i < 4; ++i) bytes += static_cast<char>(v >> (8 * i));
    };
    u32(2);
    u32(static_cast<uint32_t>(20 + json.size()));
    u32(static_cast<uint32_t>(json.size()));
    u32(0x4E4F534A);
    bytes += json;
    std::ofstream(glb, std::ios::binary) << bytes.substr(0, 40);
  }
  bad.push_back(glb);
  for (const auto& f : bad) {
    const auto b = run_dspbr("scene analyze " + f);
    EXPECT_EQ(b.status, 2) << f << "\n" << b.output;
    EXPECT_EQ(count_lines_with(b.output, "dspbr: error: " + f), 1) << b.output;
  }
}

// `scene analyze` over many scenes in one call (issue 47): a folder expands to its scenes, the
// summary is the union of what they need, the tables are named in the chosen layout, and --strict
// exits 1 when a material has a note (an unmapped extension, an approximate mapping) and 0 when
// none has.
TEST(SceneCli, AnalyzeManyScenesStrictAndLayout) {
  const auto all = run_dspbr("scene analyze " + kScenes + " --strict --json");
  ASSERT_EQ(all.status, 0) << all.output.substr(0, 2000);
  const Json j = Json::parse(all.output);
  std::size_t files = 0;
  uint32_t components = 0;
  for (const auto& e : std::filesystem::directory_iterator(kScenes))
    if (e.path().extension() == ".gltf") {
      ++files;
      components |= analyze_scene(e.path().string()).components;
    }
  ASSERT_EQ(j["scenes"].size(), files);
  EXPECT_EQ(j["summary"]["scenes"], files);
  EXPECT_EQ(j["summary"]["components"], Json(component_names(components)));
  EXPECT_EQ(j["summary"]["findings"], 0);
  // The renderer layout by default: the opaque dielectric's base reads GGX_beta, not Base_E.
  const auto tables = j["summary"]["tables"].get<std::vector<std::string>>();
  EXPECT_NE(std::find(tables.begin(), tables.end(), "GGX_beta"), tables.end());
  EXPECT_EQ(std::find(tables.begin(), tables.end(), "Base_E"), tables.end());
  const Json pub = Json::parse(run_dspbr("scene analyze " + kScenes + "13-clearcoat-0.3.gltf --layout published --json").output);
  EXPECT_EQ(pub["tables"], Json(tables_for_scene(kScenes + "13-clearcoat-0.3.gltf")));

  // An unmapped extension and KHR anisotropy (approximate): notes, and --strict fails on them.
  const std::string dir = testing::TempDir() + "dspbr_strict/";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "odd.gltf") << R"({"asset":{"version":"2.0"},"materials":[{"name":"a",
      "extensions":{"KHR_materials_unknown_thing":{}}},{"name":"b",
      "extensions":{"KHR_materials_anisotropy":{"anisotropyStrength":0.5}}}]})";
  const auto loose = run_dspbr("scene analyze " + dir + "odd.gltf");
  EXPECT_EQ(loose.status, 0) << loose.output;
  EXPECT_NE(loose.output.find("KHR_materials_unknown_thing is not mapped"), std::string::npos) << loose.output;
  EXPECT_NE(loose.output.find("approximate mapping: KHR_materials_anisotropy"), std::string::npos) << loose.output;
  const auto strict = run_dspbr("scene analyze " + dir + " " + kScenes + "13-clearcoat-0.3.gltf --strict");
  EXPECT_EQ(strict.status, 1) << strict.output;
  EXPECT_NE(strict.output.find("--strict: 2 finding(s)"), std::string::npos) << strict.output;
  EXPECT_NE(strict.output.find("summary: 2 scene(s), 3 material(s)"), std::string::npos) << strict.output;
  // A folder without scenes is bad input.
  std::filesystem::create_directories(dir + "empty");
  EXPECT_EQ(run_dspbr("scene analyze " + dir + "empty").status, 2);
  std::filesystem::remove_all(dir);
}
