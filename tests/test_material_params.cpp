// Material fields by JSON id: the list matches params-2025x.json's generic material, and the
// defaults of Material equal the file's defaults.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "dspbr/params/material_params.h"

using namespace dspbr;

TEST(MaterialParams, IdsAndDefaultsMatchParameterFile) {
  std::ifstream in(DSPBR_REFERENCE_DIR "/params-2025x.json");
  ASSERT_TRUE(in) << "missing " DSPBR_REFERENCE_DIR "/params-2025x.json";
  const auto doc = nlohmann::json::parse(in);
  const auto& params = doc["materials"]["generic"]["parameters"];
  EXPECT_EQ(params.size(), material_parameter_ids().size());
  const Material m;
  for (const auto& [id, def] : params.items()) {
    ASSERT_NO_THROW(material_parameter_kind(id)) << id;
    EXPECT_EQ(get_material_parameter(m, id), def["default"]) << id;
    EXPECT_EQ(material_parameter_ids()[def["uiOrder"].get<int>()], id);
  }
}

TEST(MaterialParams, SetParsesAndRejects) {
  Material m;
  set_material_parameter(m, "albedo", parse_parameter_text("albedo", "0.1,0.2,0.3"));
  EXPECT_DOUBLE_EQ(m.albedo.g, 0.2);
  set_material_parameter(m, "attenuationDistance", parse_parameter_text("attenuationDistance", "inf"));
  EXPECT_TRUE(std::isinf(m.attenuationDistance));
  set_material_parameter(m, "emissionMode", parse_parameter_text("emissionMode", "LUMINOUS_POWER"));
  EXPECT_EQ(m.emissionMode, EmissionMode::LuminousPower);
  EXPECT_THROW(set_material_parameter(m, "roughnes", 0.3), std::invalid_argument);
  EXPECT_THROW(set_material_parameter(m, "albedo", nlohmann::json::array({1, 2})), std::invalid_argument);
  EXPECT_THROW(set_material_parameter(m, "thinWalled", 1), std::invalid_argument);
  EXPECT_THROW(parse_parameter_text("roughness", "0.3x"), std::invalid_argument);
  EXPECT_THROW(set_material_parameter(m, "emissionMode", "LUX"), std::invalid_argument);
}
