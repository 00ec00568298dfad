// validate_material against the ranges of params-2025x.json (read here directly, independently of
// the library's hard-coded checks).
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "dspbr/material.h"
#include "dspbr/params/material_params.h"

using namespace dspbr;
using Json = nlohmann::json;

namespace {

const Json& generic_params() {
  static const Json j = [] {
    std::ifstream f(DSPBR_REFERENCE_DIR "/params-2025x.json");
    return Json::parse(f)["materials"]["generic"]["parameters"];
  }();
  return j;
}

bool accepts(const std::string& id, const Json& value) {
  Material m;
  set_material_parameter(m, id, value);
  try {
    validate_material(m);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

Json bound(const Json& b) { return b.is_object() ? Json(std::numeric_limits<double>::infinity()) : b; }

}  // namespace

TEST(BsdfValidate, DefaultsAreValid) { EXPECT_NO_THROW(validate_material(Material{})); }

TEST(BsdfValidate, FloatRangesFollowTheParameterFile) {
  int checked = 0;
  for (const auto& [id, def] : generic_params().items()) {
    if (def["type"] != "float") continue;
    ASSERT_TRUE(def.contains("min")) << id;
    const double lo = def["min"].get<double>();
    EXPECT_TRUE(accepts(id, lo)) << id;
    EXPECT_FALSE(accepts(id, lo - 1e-9)) << id;
    if (def.contains("max")) {
      const double hi = def["max"].get<double>();
      EXPECT_TRUE(accepts(id, hi)) << id;
      EXPECT_FALSE(accepts(id, hi + 1e-9)) << id;
    } else {
      EXPECT_TRUE(accepts(id, 1e30)) << id;
    }
    EXPECT_FALSE(accepts(id, std::numeric_limits<double>::quiet_NaN())) << id;
    ++checked;
  }
  EXPECT_EQ(checked, 23);  // the float parameters of the generic material
  // +inf is legal only where the file's default is +inf.
  EXPECT_TRUE(accepts("attenuationDistance", std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(accepts("roughness", std::numeric_limits<double>::infinity()));
}

TEST(BsdfValidate, ColorRangesFollowTheParameterFile) {
  for (const auto& [id, def] : generic_params().items()) {
    if (def["type"] != "color") continue;
    EXPECT_TRUE(accepts(id, Json::array({0, 0, 0}))) << id;
    EXPECT_FALSE(accepts(id, Json::array({0, -1e-9, 0}))) << id;
    if (def.contains("max")) {
      const double hi = bound(def["max"][0]).get<double>();
      EXPECT_TRUE(accepts(id, Json::array({hi, hi, hi}))) << id;
      EXPECT_FALSE(accepts(id, Json::array({hi, hi, hi + 1e-9}))) << id;
    } else {
      EXPECT_TRUE(accepts(id, Json::array({1e6, 1, 1}))) << id;
    }
  }
}

TEST(BsdfValidate, NormalsMustBeNonZeroAndMessagesNameTheField) {
  EXPECT_FALSE(accepts("normal", Json::array({0, 0, 0})));
  EXPECT_FALSE(accepts("clearcoatNormal", Json::array({0, 0, 0})));
  EXPECT_TRUE(accepts("normal", Json::array({0, 0, 2})));  // normalized by the BSDF
  Material m;
  m.specular = 1.2;
  try {
    validate_material(m);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "parameter 'specular' = 1.2 is outside [0, 1]");
  }
}
