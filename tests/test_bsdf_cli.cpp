// End-to-end tests of `dspbr eval` / `dspbr sample` through the built tool.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "dspbr/bsdf/material_bsdf.h"
#include "test_params_run.h"

using dspbr::Material;
using dspbr::MaterialBsdf;
using dspbr::Rgb;
using dspbr::Vec3;
using Json = nlohmann::json;

namespace {

Json run_json(const std::string& args) {
  const ToolRun r = run_dspbr(args);
  EXPECT_EQ(r.status, 0) << r.output;
  try {
    return Json::parse(r.output);
  } catch (const std::exception&) {
    ADD_FAILURE() << "not JSON: " << r.output;
    return Json();
  }
}


std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(BsdfCli, EvalOfALambertianMaterialIsAlbedoOverPi) {
  // specular = 0: the opaque dielectric is rho B_u = rho / pi (closed form).
  const Json j = run_json("eval --set specular=0 --set albedo=0.2,0.4,0.8 --view 0.3,0,1 --light -0.5,0.2,1");
  ASSERT_TRUE(j.contains("f"));
  EXPECT_NEAR(j["f"][0].get<double>(), 0.2 / M_PI, 1e-15);
  EXPECT_NEAR(j["f"][2].get<double>(), 0.8 / M_PI, 1e-15);
  const Vec3 l = dspbr::normalize(Vec3{-0.5, 0.2, 1});
  EXPECT_NEAR(j["pdf"].get<double>(), l.z / M_PI, 1e-15);  // cosine sampling of the only lobe
  EXPECT_NEAR(j["cos_light"].get<double>(), l.z, 1e-15);
}

TEST(BsdfCli, EvalMatchesTheLibraryAndNormalizesDirections) {
  Material m;
  m.roughness = 0.35;
  m.metallic = 0.4;
  m.albedo = Rgb(0.9, 0.6, 0.3);
  m.sheenColor = Rgb(0.5, 0.5, 0.5);
  const MaterialBsdf b(m);
  const Vec3 v = dspbr::normalize(Vec3{0.2, 0.1, 1}), l = dspbr::normalize(Vec3{-0.4, 0.3, 1});
  const Json j = run_json(
      "eval --set roughness=0.35 --set metallic=0.4 --set albedo=0.9,0.6,0.3 --set sheenColor=0.5,0.5,0.5 "
      "--view 0.4,0.2,2 --light -0.4,0.3,1");
  const Rgb f = b.eval(v, l);
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(j["f"][c].get<double>(), f[c]);
  EXPECT_DOUBLE_EQ(j["pdf"].get<double>(), b.pdf(v, l));
}

TEST(BsdfCli, MaterialFileAndSetAgree) {
  const std::string file = temp_file("bsdf_cli_material.json",
                                     R"({"material": "generic", "values": {"roughness": 0.3, "metallic": 1, "albedo": [1, 0.8, 0.5]}})");
  const Json a = run_json("eval --material " + file + " --view 0,0.3,1 --light 0.2,-0.3,1");
  const Json b = run_json("eval --set roughness=0.3 --set metallic=1 --set albedo=1,0.8,0.5 --view 0,0.3,1 --light 0.2,-0.3,1");
  EXPECT_EQ(a["f"], b["f"]);
  EXPECT_EQ(a["pdf"], b["pdf"]);
  // --set applies on top of the file.
  const Json c = run_json("eval --material " + file + " --set roughness=0.6 --view 0,0.3,1 --light 0.2,-0.3,1");
  EXPECT_NE(a["f"], c["f"]);
}

TEST(BsdfCli, SampleReportsDeltaAndGlossySamples) {
  const Json d = run_json("sample --set metallic=1 --set albedo=0.5,0.5,0.5 --view 0.5,0,1 --u 0.3,0.3,0.3");
  ASSERT_TRUE(d["valid"].get<bool>());
  EXPECT_EQ(d["flags"], Json::array({"reflection", "delta"}));
  const double c = 1 / std::sqrt(1.25);
  EXPECT_NEAR(d["weight"][0].get<double>(), 0.5 + 0.5 * std::pow(1 - c, 5), 1e-12);  // F(v.n; rho, 1)
  EXPECT_NEAR(d["l"][0].get<double>(), -0.5 * c, 1e-12);
  const Json g = run_json("sample --set roughness=0.5 --view 0.5,0,1 --u 0.3,0.7,0.2");
  ASSERT_TRUE(g["valid"].get<bool>());
  const double cos_l = std::abs(g["l"][2].get<double>()), pdf = g["pdf"].get<double>();
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(g["weight"][k].get<double>(), g["f"][k].get<double>() * cos_l / pdf, 1e-12);
}

TEST(BsdfCli, BadInputIsAOneLineUsageError) {
  expect_usage_error("eval --set roughness=1.5 --view 0,0,1 --light 0,0,1", "roughness");
  expect_usage_error("eval --set glossiness=0.5 --view 0,0,1 --light 0,0,1", "glossiness");
  expect_usage_error("eval --set roughness --view 0,0,1 --light 0,0,1", "id=value");
  expect_usage_error("eval --set albedo=1,2 --view 0,0,1 --light 0,0,1", "albedo");
  expect_usage_error("eval --view 0,0 --light 0,0,1", "--view");
  expect_usage_error("eval --view 0,0,0 --light 0,0,1", "non-zero");
  expect_usage_error("eval --view 0,0,1 --light 0,x,1", "--light");
  expect_usage_error("sample --view 0,0,1 --u 0.5,0.5,1", "--u");
  expect_usage_error("eval --material /nonexistent/m.json --view 0,0,1 --light 0,0,1", "m.json");
  const std::string bad = temp_file("bsdf_cli_bad.json", "{\"material\": \"generic\", \"values\": {");
  expect_usage_error("eval --material " + bad + " --view 0,0,1 --light 0,0,1", "bsdf_cli_bad.json");
  expect_usage_error("eval --components glitter --view 0,0,1 --light 0,0,1", "glitter");
  // A missing required option is CLI11's usage error: non-zero exit.
  EXPECT_NE(run_dspbr("eval --view 0,0,1").status, 0);
}

TEST(BsdfCli, OtherMaterialTypesLoadThroughTheirDefinitions) {
  // A "glass" instance (params-2025x.json subtype): its defaults make a volumetric transparent material.
  const Json j = run_json("eval --material " DSPBR_SOURCE_DIR "/tests/data/params/glass_ok.json --view 0,0.5,1 --light 0,-0.5,-1");
  ASSERT_TRUE(j.contains("components"));
  EXPECT_EQ(j["components"], Json::array({"volumetric_transparent"}));
  EXPECT_GT(j["f"][1].get<double>(), 0.0);
}
