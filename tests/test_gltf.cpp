// glTF reading (.gltf, .glb) and the glTF -> DSPBR parameter mapping (docs/gltf_mapping.md).
// Expected values are read from the glTF JSON in the test (the shared validation scenes and the
// hand-made files under tests/data/gltf), or follow from the extensions' published definitions
// (e.g. dispersion = 20 / Abbe number, rotation in radians -> turns).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/gltf/gltf_file.h"
#include "dspbr/gltf/gltf_material.h"
#include "dspbr/params/material_params.h"
#include "test_params_run.h"

using namespace dspbr;
using namespace dspbr::gltf;
using Json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

const std::string kScenes = DSPBR_REFERENCE_DIR "/scenes/sphere";
const std::string kData = DSPBR_SOURCE_DIR "/tests/data/gltf/";

Json read_json(const std::string& path) {
  std::ifstream in(path);
  return Json::parse(in);
}

std::vector<std::string> shared_scenes() {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(kScenes))
    if (e.path().extension() == ".gltf") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

const GltfMaterial& by_name(const std::vector<GltfMaterial>& ms, const std::string& name) {
  for (const auto& m : ms)
    if (m.name == name) return m;
  throw std::runtime_error("no material " + name);
}

void expect_rgb(const Rgb& c, const Json& a, const std::string& what) {
  ASSERT_TRUE(a.is_array() && a.size() >= 3) << what;
  EXPECT_DOUBLE_EQ(c.r, a[0].get<double>()) << what;
  EXPECT_DOUBLE_EQ(c.g, a[1].get<double>()) << what;
  EXPECT_DOUBLE_EQ(c.b, a[2].get<double>()) << what;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// GLB container built here independently of the reader: 12-byte header, JSON chunk padded with
// spaces, BIN chunk padded with zeros (glTF 2.0 "GLB File Format Specification").
std::vector<std::uint8_t> make_glb(const std::string& json, const std::vector<std::uint8_t>& bin) {
  std::vector<std::uint8_t> out;
  auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  };
  std::string j = json;
  while (j.size() % 4) j += ' ';
  std::vector<std::uint8_t> b = bin;
  while (b.size() % 4) b.push_back(0);
  u32(0x46546C67);
  u32(2);
  u32(static_cast<std::uint32_t>(12 + 8 + j.size() + (b.empty() ? 0 : 8 + b.size())));
  u32(static_cast<std::uint32_t>(j.size()));
  u32(0x4E4F534A);
  out.insert(out.end(), j.begin(), j.end());
  if (!b.empty()) {
    u32(static_cast<std::uint32_t>(b.size()));
    u32(0x004E4942);
    out.insert(out.end(), b.begin(), b.end());
  }
  return out;
}

std::string write_temp(const std::string& name, const std::vector<std::uint8_t>& bytes) {
  const std::string path = testing::TempDir() + name;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  return path;
}

// materials.gltf as a .glb: buffer 0 becomes the BIN chunk.
std::vector<std::uint8_t> materials_glb() {
  Json doc = read_json(kData + "materials.gltf");
  doc["buffers"][0].erase("uri");
  std::vector<std::uint8_t> bin(24);
  for (int i = 0; i < 24; ++i) bin[i] = static_cast<std::uint8_t>(i);
  return make_glb(doc.dump(), bin);
}

}  // namespace

TEST(Gltf, EverySharedSceneParsesAndMaps) {
  const auto files = shared_scenes();
  ASSERT_GE(files.size(), 70u);
  for (const auto& f : files) {
    SCOPED_TRACE(f);
    GltfFile g;
    ASSERT_NO_THROW(g = read_gltf(f));
    std::vector<GltfMaterial> ms;
    ASSERT_NO_THROW(ms = map_materials(g));
    EXPECT_EQ(ms.size(), read_json(f)["materials"].size());
  }
}

// Each mapped value of every shared scene against the numbers in the file. The table below is the
// mapping of docs/gltf_mapping.md for the properties that occur in the scenes.
TEST(Gltf, SharedScenesMapToTheirOwnNumbers) {
  struct Scalar {
    const char* ext;
    const char* key;
    const char* param;
  };
  const Scalar scalars[] = {
      {"KHR_materials_specular", "specularFactor", "specular"},
      {"KHR_materials_ior", "ior", "ior"},
      {"KHR_materials_clearcoat", "clearcoatFactor", "clearcoat"},
      {"KHR_materials_clearcoat", "clearcoatRoughnessFactor", "clearcoatRoughness"},
      {"KHR_materials_sheen", "sheenRoughnessFactor", "sheenRoughness"},
      {"3DS_materials_anisotropy", "anisotropyFactor", "anisotropy"},
      {"3DS_materials_anisotropy", "anisotropyRotationFactor", "anisotropyRotation"},
      {"3DS_materials_translucency", "translucencyFactor", "translucency"},
  };
  int checked = 0;
  for (const auto& f : shared_scenes()) {
    SCOPED_TRACE(f);
    const Json doc = read_json(f);
    const auto ms = map_materials(read_gltf(f));
    for (std::size_t i = 0; i < ms.size(); ++i) {
      const Json& mat = doc["materials"][i];
      const Material& m = ms[i].material;
      const Json& pbr = mat["pbrMetallicRoughness"];
      expect_rgb(m.albedo, pbr["baseColorFactor"], "albedo");
      EXPECT_DOUBLE_EQ(m.metallic, pbr["metallicFactor"].get<double>());
      EXPECT_DOUBLE_EQ(m.roughness, pbr["roughnessFactor"].get<double>());
      Json exts = mat.value("extras", Json::object());
      const Json extensions = mat.value("extensions", Json::object());
      for (const auto& [k, v] : extensions.items()) exts[k] = v;
      for (const auto& s : scalars) {
        if (!exts.contains(s.ext) || !exts[s.ext].contains(s.key)) continue;
        EXPECT_DOUBLE_EQ(get_material_parameter(m, s.param).get<double>(), exts[s.ext][s.key].get<double>()) << s.param;
        ++checked;
      }
      if (exts.contains("KHR_materials_specular") && exts["KHR_materials_specular"].contains("specularColorFactor"))
        expect_rgb(m.specularTint, exts["KHR_materials_specular"]["specularColorFactor"], "specularTint"), ++checked;
      if (exts.contains("KHR_materials_sheen"))
        expect_rgb(m.sheenColor, exts["KHR_materials_sheen"]["sheenColorFactor"], "sheenColor"), ++checked;
      // Absent extensions leave the DSPBR defaults (glTF and DSPBR agree there).
      const Material d;
      if (!exts.contains("KHR_materials_clearcoat")) EXPECT_EQ(m.clearcoat, 0.0);
      if (!exts.contains("KHR_materials_ior")) EXPECT_EQ(m.ior, 1.5);
      if (!exts.contains("KHR_materials_specular")) EXPECT_EQ(m.specular, 1.0);
      EXPECT_EQ(m.transparency, 0.0);
      EXPECT_TRUE(m.thinWalled);
      EXPECT_EQ(m.flakeCoverage, d.flakeCoverage);
      EXPECT_EQ(m.cutoutOpacity, 1.0);  // alphaMode OPAQUE
      EXPECT_EQ(m.emissionColor.max_component() * m.emissionValue, 0.0);
    }
  }
  EXPECT_GE(checked, 80);
}

TEST(Gltf, HandMadeMaterialsMapAllExtensions) {
  const Json doc = read_json(kData + "materials.gltf");
  const auto ms = map_materials(read_gltf(kData + "materials.gltf"));
  ASSERT_EQ(ms.size(), 3u);
  const auto& paint = by_name(ms, "textured_paint");
  const Json& pm = doc["materials"][0];
  expect_rgb(paint.material.albedo, pm["pbrMetallicRoughness"]["baseColorFactor"], "albedo");
  EXPECT_EQ(paint.material.cutoutOpacity, pm["pbrMetallicRoughness"]["baseColorFactor"][3].get<double>());  // BLEND
  EXPECT_EQ(paint.material.transparency, 1.0);
  EXPECT_FALSE(paint.material.thinWalled);  // volume thickness > 0
  EXPECT_EQ(paint.material.attenuationDistance, pm["extensions"]["KHR_materials_volume"]["attenuationDistance"].get<double>());
  expect_rgb(paint.material.attenuationColor, pm["extensions"]["KHR_materials_volume"]["attenuationColor"], "attenuationColor");
  // KHR_materials_dispersion defines dispersion = 20 / V_d.
  EXPECT_DOUBLE_EQ(paint.material.abbeNumber * pm["extensions"]["KHR_materials_dispersion"]["dispersion"].get<double>(), 20.0);
  const std::vector<std::string> textured{"albedo", "metallic", "roughness", "cutoutOpacity", "normal",
                                          "emissionColor", "transparency", "clearcoat"};
  EXPECT_EQ(paint.textured_parameters(), textured);
  bool occlusion_reported = false;
  for (const auto& t : paint.textures) occlusion_reported |= t.source == "occlusionTexture" && t.parameter.empty();
  EXPECT_TRUE(occlusion_reported);
  ASSERT_EQ(paint.notes.size(), 1u);
  EXPECT_NE(paint.notes[0].find("KHR_materials_unlit"), std::string::npos);

  const auto& all = by_name(ms, "everything");
  const Json& ae = doc["materials"][1]["extensions"];
  // glTF emissive * strength is luminance; DSPBR luminance is l_v l_c / pi (spec "Emission").
  const double strength = ae["KHR_materials_emissive_strength"]["emissiveStrength"].get<double>();
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(all.material.emissionColor[c] * all.material.emissionValue / M_PI,
                doc["materials"][1]["emissiveFactor"][c].get<double>() * strength, 1e-12);
  EXPECT_EQ(all.material.emissionMode, EmissionMode::LuminousEmittance);
  EXPECT_EQ(all.material.thinFilm, ae["KHR_materials_iridescence"]["iridescenceFactor"].get<double>());
  EXPECT_EQ(all.material.thinFilmIor, ae["KHR_materials_iridescence"]["iridescenceIor"].get<double>());
  EXPECT_DOUBLE_EQ(all.material.thinFilmThickness * 1000.0,  // microns vs nm
                   ae["KHR_materials_iridescence"]["iridescenceThicknessMaximum"].get<double>());
  EXPECT_EQ(all.material.anisotropy, ae["KHR_materials_anisotropy"]["anisotropyStrength"].get<double>());
  // -pi/2 radians counter-clockwise = 1/4 turn clockwise, DSPBR's sense (docs/gltf_mapping.md).
  EXPECT_NEAR(all.material.anisotropyRotation, 0.25, 1e-15);
  EXPECT_EQ(all.material.translucency, ae["KHR_materials_diffuse_transmission"]["diffuseTransmissionFactor"].get<double>());
  expect_rgb(all.material.translucencyColor, ae["KHR_materials_diffuse_transmission"]["diffuseTransmissionColorFactor"], "tc");
  expect_rgb(all.material.sheenColor, ae["KHR_materials_sheen"]["sheenColorFactor"], "sheen");
  const Json& sss = doc["materials"][1]["extras"]["3DS_materials_sss"];
  expect_rgb(all.material.subsurfaceColor, sss["subsurfaceColor"], "subsurfaceColor");
  EXPECT_EQ(all.material.subsurfaceAnisotropy, sss["subsurfaceAsymmetry"].get<double>());
  EXPECT_TRUE(all.textures.empty());

  const auto& em = by_name(ms, "ds_emitter");
  const Json& de = doc["materials"][2];
  expect_rgb(em.material.emissionColor, de["emissiveFactor"], "emissionColor");
  EXPECT_EQ(em.material.emissionValue, de["extensions"]["3DS_materials_emission"]["emissionValue"].get<double>());
  EXPECT_EQ(em.material.emissionMode, EmissionMode::LuminousPower);
  EXPECT_TRUE(em.material.emissionEnergyNormalization);
  EXPECT_EQ(em.material.roughness, 1.0);  // glTF default roughnessFactor
  EXPECT_EQ(em.material.anisotropyRotation, de["extensions"]["3DS_materials_anisotropy"]["anisotropyRotationFactor"].get<double>());
}

TEST(Gltf, GlbEqualsGltf) {
  const auto glb_path = write_temp("dspbr_materials.glb", materials_glb());
  const GltfFile glb = read_gltf(glb_path);
  EXPECT_TRUE(glb.binary);
  ASSERT_EQ(glb.buffer_sizes.size(), 1u);
  EXPECT_EQ(glb.buffer_sizes[0], 24u);
  const auto a = map_materials(glb), b = map_materials(read_gltf(kData + "materials.gltf"));
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    for (const auto& id : material_parameter_ids())
      EXPECT_EQ(get_material_parameter(a[i].material, id), get_material_parameter(b[i].material, id)) << id;
}

TEST(Gltf, BadInputsGiveClearErrors) {
  const std::pair<const char*, const char*> cases[] = {
      {"missing_buffer.gltf", "cannot read buffer file"},
      {"short_buffer.gltf", "declares 48 bytes but only 24"},
      {"view_outside_buffer.gltf", "lies outside buffer 0"},
      {"wrong_types.gltf", "metallicFactor must be a number"},
      {"wrong_length.gltf", "sheenColorFactor must be an array of 3 numbers"},
      {"bad_texture.gltf", "refers to texture 7"},
      {"malformed.gltf", "malformed JSON"},
      {"not_gltf.gltf", "not a glTF asset"},
      {"no_such_file.gltf", "does not exist"},
  };
  for (const auto& [file, message] : cases) {
    const std::string e = error_of([&] { map_materials(read_gltf(kData + file)); });
    EXPECT_NE(e.find(message), std::string::npos) << file << ": " << e;
    EXPECT_NE(e.find(file), std::string::npos) << e;
  }
  // A texture index is named as written (issue 45, poor list: 2^64 - 1 was "texture -1").
  for (const std::string index : {"18446744073709551615", "9223372036854775808", "-1", "1"}) {
    const std::string text = R"({"asset": {"version": "2.0"}, "textures": [{}], "materials": [{"name": "m",
        "pbrMetallicRoughness": {"baseColorTexture": {"index": )" + index + "}}}]}";
    const std::string e = error_of([&] { map_materials(parse_gltf(std::vector<std::uint8_t>(text.begin(), text.end()), "t.gltf")); });
    EXPECT_NE(e.find("baseColorTexture refers to texture " + index + ", which does not exist"), std::string::npos) << e;
  }
  // Broken GLB containers.
  const auto good = materials_glb();
  auto truncated = good;
  truncated.resize(good.size() - 10);
  EXPECT_NE(error_of([&] { parse_gltf(truncated, "t.glb"); }).find("truncated"), std::string::npos);
  auto chunk_too_long = good;
  chunk_too_long[12] = 0xff, chunk_too_long[13] = 0xff;  // JSON chunk length beyond the file
  EXPECT_NE(error_of([&] { parse_gltf(chunk_too_long, "c.glb"); }).find("chunk 0 declares"), std::string::npos);
  auto version = good;
  version[4] = 1;
  EXPECT_NE(error_of([&] { parse_gltf(version, "v.glb"); }).find("version 1"), std::string::npos);
  std::vector<std::uint8_t> header_only(good.begin(), good.begin() + 8);
  EXPECT_NE(error_of([&] { parse_gltf(header_only, "h.glb"); }).find("header"), std::string::npos);
  auto no_bin = make_glb(read_json(kData + "materials.gltf").dump(), {});
  Json no_uri = read_json(kData + "materials.gltf");
  no_uri["buffers"][0].erase("uri");
  EXPECT_NE(error_of([&] { parse_gltf(make_glb(no_uri.dump(), {}), "n.glb"); }).find("BIN chunk, which is missing"),
            std::string::npos);
  EXPECT_NO_THROW(parse_gltf(no_bin, "data-uri.glb"));  // buffer 0 keeps its data URI
}

// A buffer file that is a Git LFS pointer: accepted with a warning when it announces enough bytes.
TEST(Gltf, LfsPointerBufferIsAWarning) {
  const std::string dir = testing::TempDir() + "dspbr_lfs/";
  fs::create_directories(dir);
  std::ofstream(dir + "geo.bin") << "version https://git-lfs.github.com/spec/v1\noid sha256:00\nsize 24\n";
  Json doc = read_json(kData + "materials.gltf");
  doc["buffers"][0]["uri"] = "geo.bin";
  std::ofstream(dir + "lfs.gltf") << doc.dump();
  const GltfFile f = read_gltf(dir + "lfs.gltf");
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("Git LFS pointer"), std::string::npos);
  doc["buffers"][0]["byteLength"] = 25;
  std::ofstream(dir + "lfs_short.gltf") << doc.dump();
  EXPECT_NE(error_of([&] { read_gltf(dir + "lfs_short.gltf"); }).find("less than the declared byteLength"), std::string::npos);
}

// KHR_materials_anisotropy turns the anisotropy direction counter-clockwise (tangent towards
// bitangent). Turning a material by theta that way is the same as turning the viewer and the light
// by -theta about the normal: f_theta(v, l) = f_0(R(-theta) v, R(-theta) l). The material turned
// through 3DS_materials_anisotropy (DSPBR's own rotation) by the same direction agrees; the opposite
// turn must not (the check's power).
// Values outside an extension's own range get a note (found by the fourth fresh tester's pass: a
// negative dispersion became "no dispersion" and attenuationDistance 0 was kept, without a word).
TEST(Gltf, ValuesOutsideAnExtensionsRangeAreNoted) {
  const Json doc = {{"asset", {{"version", "2.0"}}},
                    {"materials",
                     {{{"name", "m"},
                       {"extensions",
                        {{"KHR_materials_dispersion", {{"dispersion", -1}}},
                         {"KHR_materials_volume", {{"thicknessFactor", 1}, {"attenuationDistance", 0}}},
                         {"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}}}}};
  const std::string text = doc.dump();
  const auto ms = map_materials(parse_gltf(std::vector<std::uint8_t>(text.begin(), text.end()), "m.gltf"));
  std::string notes;
  for (const auto& n : ms.at(0).notes) notes += n + "\n";
  EXPECT_NE(notes.find("KHR_materials_dispersion.dispersion -1.0 must be at least 0; mapped to no dispersion"),
            std::string::npos) << notes;
  EXPECT_NE(notes.find("KHR_materials_volume.attenuationDistance 0.0 must be above 0"), std::string::npos) << notes;
  EXPECT_EQ(ms.at(0).material.abbeNumber, 0.0);
}

TEST(Gltf, KhrRotationTurnsCounterClockwise) {
  const double theta = 0.6;
  auto material_of = [](const Json& ext) {
    Json doc = {{"asset", {{"version", "2.0"}}},
                {"materials",
                 {{{"name", "m"},
                   {"pbrMetallicRoughness", {{"metallicFactor", 1.0}, {"roughnessFactor", 0.5}}},
                   {"extensions", ext}}}}};
    const std::string text = doc.dump();
    const auto ms = map_materials(parse_gltf(std::vector<std::uint8_t>(text.begin(), text.end()), "m.gltf"));
    return ms.at(0).material;
  };
  const Material khr = material_of(
      {{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.8}, {"anisotropyRotation", theta}}}});
  const Material ds = material_of({{"3DS_materials_anisotropy",
                                    {{"anisotropyFactor", 0.8}, {"anisotropyRotationFactor", 1.0 - theta / (2 * M_PI)}}}});
  const Material flat = material_of({{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.8}}}});
  const MaterialBsdf f_khr(khr), f_ds(ds), f_flat(flat);
  auto turn = [](const Vec3& w, double a) {
    return Vec3{w.x * std::cos(a) - w.y * std::sin(a), w.x * std::sin(a) + w.y * std::cos(a), w.z};
  };
  auto dir = [](double th_deg, double ph_deg) {
    const double th = th_deg * M_PI / 180, ph = ph_deg * M_PI / 180;
    return Vec3{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
  };
  double worst_wrong = 0;
  for (double ph : {0.0, 30.0, 75.0, 140.0}) {
    const Vec3 v = dir(50, ph), l = dir(35, ph + 160);
    const double expected = f_flat.eval(turn(v, -theta), turn(l, -theta)).g;
    EXPECT_NEAR(f_khr.eval(v, l).g, expected, 1e-12 * expected);
    EXPECT_NEAR(f_ds.eval(v, l).g, expected, 1e-9 * expected);
    const double wrong = f_flat.eval(turn(v, theta), turn(l, theta)).g;
    worst_wrong = std::max(worst_wrong, std::abs(wrong - expected) / expected);
  }
  EXPECT_GT(worst_wrong, 0.05);  // the clockwise reading would have failed
}
