// Parameter definition files (spec appendix "Parameter JSON file format") and material
// instances. Expected values come from the raw JSON files read here (the official
// params-2025x.json, hand-made files under tests/data/params) and from the spec's rules
// (type-derived defaults, recursive merge, '' group first), never from the resolver's output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "dspbr/params/material_instance.h"
#include "dspbr/params/param_defs.h"
#include "test_params_run.h"

using namespace dspbr;
using Json = nlohmann::json;

namespace {

const std::string kOfficial = DSPBR_REFERENCE_DIR "/params-2025x.json";
const std::string kData = DSPBR_SOURCE_DIR "/tests/data/params/";

Json read_json(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  return Json::parse(in);
}

std::string load_error(const std::string& path) {
  try {
    ParamDefs::load(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

Json instance_file(const std::string& name) { return read_json(kData + name); }

}  // namespace

// Every subtype of the official file against a one-level merge done here from the raw JSON:
// a property comes from the subtype when it gives it, else from "generic", else from the type.
TEST(ParamDefs, OfficialFileResolvesEverySubtype) {
  const Json raw = read_json(kOfficial);
  const ParamDefs defs = ParamDefs::load(kOfficial);
  const Json& generic = raw["materials"]["generic"]["parameters"];
  for (const auto& [mid, mraw] : raw["materials"].items()) {
    SCOPED_TRACE(mid);
    const MaterialDef& m = defs.material(mid);
    EXPECT_EQ(m.parameters.size(), generic.size());
    for (const auto& [pid, gp] : generic.items()) {
      SCOPED_TRACE(pid);
      const ParamDef* d = m.find(pid);
      ASSERT_NE(d, nullptr);
      const Json own = mraw["parameters"].value(pid, Json::object());
      auto prop = [&](const char* key, const Json& fallback) {
        return own.contains(key) ? own[key] : gp.value(key, fallback);
      };
      Json expected_default = prop("default", Json());
      if (expected_default.is_object() && expected_default.contains("$ref")) {
        // plastic's translucencyColor default points at another default of the same file.
        expected_default = raw.at(Json::json_pointer(expected_default["$ref"].get<std::string>().substr(1)));
      }
      if (expected_default.is_array()) {
        ASSERT_TRUE(d->default_value.is_array());
        for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(d->default_value[i].get<double>(), expected_default[i].get<double>());
      } else if (expected_default.is_number()) {
        EXPECT_DOUBLE_EQ(d->default_value.get<double>(), expected_default.get<double>());
      } else {
        EXPECT_EQ(d->default_value, expected_default);
      }
      EXPECT_EQ(d->hidden, prop("hidden", false).get<bool>());
      EXPECT_EQ(d->uniform, prop("uniform", false).get<bool>());
      EXPECT_EQ(d->group, prop("group", "").get<std::string>());
      EXPECT_EQ(d->ui_order, prop("uiOrder", -1).get<int>());
      EXPECT_EQ(param_type_name(d->type), prop("type", "").get<std::string>());
      for (const char* key : {"min", "max"}) {
        const Json expected = prop(key, Json());
        if (expected.is_null()) continue;  // type-derived: see ThreeLevelInheritanceAndTypeDerivedValues
        EXPECT_EQ(Json::parse(Json((*d).*(key[1] == 'i' ? &ParamDef::min : &ParamDef::max)).dump()),
                  Json::parse(expected.dump()).is_number() ? Json(expected.get<double>()) : [&] {
                    Json a = Json::array();
                    for (const auto& c : expected) a.push_back(c.get<double>());
                    return a;
                  }()) << key;
      }
    }
  }
}

// UI order: parameters of group '' first, then each group contiguous, uiOrder increasing inside.
// The definitions compiled into the library are those of the shipped file, material by material.
TEST(ParamDefs, BuiltinDefinitionsAreTheShippedFile) {
  const ParamDefs& builtin = ParamDefs::builtin();
  const ParamDefs file = ParamDefs::load(kOfficial);
  EXPECT_EQ(builtin.source(), "built-in params-2025x.json");
  ASSERT_EQ(builtin.material_ids(), file.material_ids());
  for (const auto& id : file.material_ids())
    EXPECT_EQ(material_def_to_json(builtin.material(id)), material_def_to_json(file.material(id))) << id;
  EXPECT_EQ(&ParamDefs::builtin(), &builtin);  // parsed once
}

TEST(ParamDefs, UiOrderPutsEmptyGroupFirst) {
  const ParamDefs defs = ParamDefs::load(kOfficial);
  for (const auto& mid : defs.material_ids()) {
    const auto& ps = defs.material(mid).parameters;
    std::set<std::string> closed;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (i > 0 && ps[i].group != ps[i - 1].group) {
        closed.insert(ps[i - 1].group);
        EXPECT_EQ(closed.count(ps[i].group), 0u) << mid << ": group '" << ps[i].group << "' split";
        EXPECT_FALSE(ps[i].group.empty()) << mid << ": '' group not first";
      }
      if (i > 0 && ps[i].group == ps[i - 1].group) EXPECT_LT(ps[i - 1].ui_order, ps[i].ui_order) << mid;
    }
  }
  // The file's own material order is kept.
  std::vector<std::string> file_order;
  std::ifstream in(kOfficial);
  const auto ordered = nlohmann::ordered_json::parse(in);
  for (const auto& [id, _] : ordered["materials"].items())
    file_order.push_back(id);
  EXPECT_EQ(defs.material_ids(), file_order);
}

// A three-level chain with type-derived values, following the spec's rules by hand.
TEST(ParamDefs, ThreeLevelInheritanceAndTypeDerivedValues) {
  const ParamDefs defs = ParamDefs::load(kData + "chain.json");
  const MaterialDef& glass = defs.material("glass");
  EXPECT_EQ(glass.name, "Glass");
  EXPECT_EQ(glass.inherits, (std::vector<std::string>{"dielectric", "base"}));
  const Json inf = {{"infinity", true}}, minus_inf = {{"-infinity", true}};
  // ior: default overridden at each level, group moved to '' by glass, min from base, max from type.
  EXPECT_EQ(glass.find("ior")->default_value, 1.52);
  EXPECT_EQ(defs.material("dielectric").find("ior")->default_value, 1.45);
  EXPECT_EQ(defs.material("base").find("ior")->default_value, 1.5);
  EXPECT_EQ(glass.find("ior")->group, "");
  EXPECT_EQ(defs.material("dielectric").find("ior")->group, "Volume");
  EXPECT_EQ(glass.find("ior")->min, 1.0);
  EXPECT_EQ(glass.find("ior")->max, inf);
  // transparency: hidden only in glass, range inherited.
  EXPECT_TRUE(glass.find("transparency")->hidden);
  EXPECT_FALSE(defs.material("dielectric").find("transparency")->hidden);
  EXPECT_EQ(glass.find("transparency")->default_value, 1.0);
  EXPECT_EQ(glass.find("transparency")->max, 1.0);
  EXPECT_EQ(defs.material("base").find("transparency")->default_value, 0.0);  // float default 0
  // Type-derived values (spec table json-types).
  EXPECT_EQ(glass.find("tint")->default_value, Json::array({0.0, 0.0, 0.0}));
  EXPECT_EQ(glass.find("tint")->min, Json::array({0.0, 0.0, 0.0}));
  EXPECT_EQ(glass.find("tint")->max, Json::array({inf, inf, inf}));
  EXPECT_EQ(glass.find("dir")->min, Json::array({minus_inf, minus_inf, minus_inf}));
  EXPECT_EQ(glass.find("n")->default_value, Json::array({0.0, 0.0, 1.0}));
  EXPECT_TRUE(glass.find("n")->min.is_null());
  EXPECT_EQ(glass.find("thin")->default_value, false);
  EXPECT_TRUE(glass.find("thin")->uniform);
  EXPECT_EQ(defs.material("base").find("mode")->default_value, "A");  // first enum value
  EXPECT_EQ(glass.find("mode")->default_value, "B");                   // from dielectric
  EXPECT_EQ(glass.find("distance")->default_value, inf);
  // UI order: '' group (tint 0, ior 3), then Base (transparency 1, dir 2), then Volume.
  std::vector<std::string> order;
  for (const auto& p : glass.parameters) order.push_back(p.id);
  EXPECT_EQ(order, (std::vector<std::string>{"tint", "ior", "transparency", "dir", "n", "thin", "mode", "distance", "extra"}));
  // --json: uninterpreted properties are kept, keys in UI order.
  const auto j = material_def_to_json(glass);
  EXPECT_EQ(j["parameters"]["extra"]["unit"], "mm");
  EXPECT_EQ(j["parameters"].begin().key(), "tint");
  EXPECT_EQ(j["parameters"]["mode"]["enum"], nlohmann::ordered_json::array({"A", "B"}));
}

TEST(ParamDefs, BadDefinitionFilesGiveClearErrors) {
  EXPECT_NE(load_error(kData + "cycle.json").find("inheritance cycle"), std::string::npos);
  EXPECT_NE(load_error(kData + "unknown_base.json").find("unknown material 'nosuchbase'"), std::string::npos);
  EXPECT_NE(load_error(kData + "bad_type.json").find("unknown type \"colour\""), std::string::npos);
  EXPECT_NE(load_error(kData + "bad_default.json").find("outside"), std::string::npos);
  EXPECT_NE(load_error(kData + "malformed.json").find("malformed JSON"), std::string::npos);
  EXPECT_NE(load_error(kData + "does_not_exist.json").find("does not exist"), std::string::npos);
  EXPECT_THROW(ParamDefs::load(kOfficial).material("unobtainium"), std::invalid_argument);
}

// Valid instances convert from the subtype's defaults (read from the raw file) plus the values.
TEST(MaterialInstance, ValidInstancesConvert) {
  const Json raw = read_json(kOfficial);
  const ParamDefs defs = ParamDefs::load(kOfficial);
  const Json inst = instance_file("glass_ok.json");
  EXPECT_TRUE(check_material_instance(defs, inst).empty());
  const Material g = material_from_instance(defs, inst);
  EXPECT_EQ(g.roughness, 0.1);
  EXPECT_TRUE(std::isinf(g.attenuationDistance));
  EXPECT_FALSE(g.thinWalled);
  EXPECT_EQ(g.attenuationColor.g, 0.95);
  // Not in the instance: the glass subtype's defaults, else generic's.
  EXPECT_EQ(g.transparency, raw["materials"]["glass"]["parameters"]["transparency"]["default"].get<double>());
  EXPECT_EQ(g.ior, raw["materials"]["generic"]["parameters"]["ior"]["default"].get<double>());

  const Material p = material_from_instance(defs, Json{{"material", "plastic"}});
  const double plastic_albedo = raw["materials"]["plastic"]["parameters"]["albedo"]["default"][0].get<double>();
  EXPECT_EQ(p.albedo.r, plastic_albedo);
  EXPECT_EQ(p.translucencyColor.r, plastic_albedo);  // "$ref" to plastic's albedo default
  EXPECT_EQ(p.attenuationDistance, raw["materials"]["plastic"]["parameters"]["attenuationDistance"]["default"].get<double>());

  const Material m = material_from_instance(defs, instance_file("generic_ok.json"));
  EXPECT_EQ(m.metallic, 0.25);
  EXPECT_EQ(m.ior, 1.52);
  EXPECT_EQ(m.emissionMode, EmissionMode::LuminousPower);
  EXPECT_EQ(m.clearcoatNormal.y, 0.6);
}

TEST(MaterialInstance, OneMessagePerProblem) {
  const ParamDefs defs = ParamDefs::load(kOfficial);
  const auto problems = check_material_instance(defs, instance_file("bad_values.json"));
  ASSERT_EQ(problems.size(), 7u);
  auto has = [&](const std::string& a, const std::string& b) {
    int n = 0;
    for (const auto& p : problems) n += p.find(a) != std::string::npos && p.find(b) != std::string::npos;
    return n == 1;
  };
  EXPECT_TRUE(has("'roughnes'", "unknown parameter"));
  EXPECT_TRUE(has("'metallic'", "wrong type"));
  EXPECT_TRUE(has("'roughness'", "out of range"));
  EXPECT_TRUE(has("'albedo'", "wrong length"));
  EXPECT_TRUE(has("'thinWalled'", "wrong type"));
  EXPECT_TRUE(has("'emissionMode'", "LUX"));
  EXPECT_TRUE(has("'normal'", "unit length"));

  const auto hidden = check_material_instance(defs, instance_file("glass_ior_hidden.json"));
  ASSERT_EQ(hidden.size(), 1u);
  EXPECT_NE(hidden[0].find("'ior' is hidden"), std::string::npos);
  const auto unknown = check_material_instance(defs, instance_file("unknown_material.json"));
  ASSERT_EQ(unknown.size(), 1u);
  EXPECT_NE(unknown[0].find("unknown material 'unobtainium'"), std::string::npos);
  EXPECT_THROW(material_from_instance(defs, instance_file("bad_values.json")), std::runtime_error);
}

TEST(MaterialInstance, LoadFromFileNamesTheFile) {
  EXPECT_EQ(load_material_instance(kData + "glass_ok.json").roughness, 0.1);
  for (const char* bad : {"malformed_instance.json", "bad_values.json", "no_such_file.json"}) {
    try {
      load_material_instance(kData + bad);
      ADD_FAILURE() << bad << " loaded";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
  // DSPBR_PARAMS overrides the definition file; chain.json's parameters have no Material field.
  setenv("DSPBR_PARAMS", (kData + "chain.json").c_str(), 1);
  std::string message;
  try {
    load_material_instance(kData + "glass_ok.json");
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  unsetenv("DSPBR_PARAMS");
  EXPECT_NE(message.find("unknown parameter 'roughness'"), std::string::npos) << message;
  // A bad file named by the variable is said to come from it (issue 45, poor list).
  setenv("DSPBR_PARAMS", (kData + "malformed_instance.json").c_str(), 1);
  const auto listed = run_dspbr("params list");
  unsetenv("DSPBR_PARAMS");
  EXPECT_EQ(listed.status, 2) << listed.output;
  EXPECT_EQ(listed.output.rfind("dspbr: error: $DSPBR_PARAMS: " + kData + "malformed_instance.json: ", 0), 0u)
      << listed.output;
}

TEST(ParamsCli, ListShowCheck) {
  const auto list = run_dspbr("params list " + kOfficial);
  EXPECT_EQ(list.status, 0) << list.output;
  EXPECT_EQ(count_lines_with(list.output, "inherits generic"), 9);

  const auto show = run_dspbr("params show " + kOfficial + " glass --json");
  ASSERT_EQ(show.status, 0) << show.output;
  const Json shown = Json::parse(show.output);
  const Json raw = read_json(kOfficial);
  ASSERT_EQ(shown["parameters"].size(), raw["materials"]["generic"]["parameters"].size());
  for (const auto& [id, p] : shown["parameters"].items())
    for (const char* key : {"name", "type", "default", "min", "max", "uniform", "hidden", "group", "uiOrder"})
      EXPECT_TRUE(p.contains(key)) << id << " lacks " << key;
  EXPECT_EQ(shown["parameters"]["transparency"]["hidden"], true);
  EXPECT_EQ(shown["parameters"]["attenuationDistance"]["default"], raw["materials"]["glass"]["parameters"]["attenuationDistance"]["default"]);

  EXPECT_EQ(run_dspbr("params check " + kData + "glass_ok.json " + kData + "generic_ok.json").status, 0);
  const auto bad = run_dspbr("params check " + kData + "bad_values.json");
  EXPECT_EQ(bad.status, 2);
  // One file: its problems on the one error line (the fourth fresh tester's pass: a line per problem
  // and a count, the first lines without "dspbr: error:").
  const auto occurrences = [&](const std::string& needle) {
    std::size_t n = 0;
    for (std::size_t at = bad.output.find(needle); at != std::string::npos; at = bad.output.find(needle, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count_lines_with(bad.output, "dspbr: error: "), 1) << bad.output;
  EXPECT_EQ(std::count(bad.output.begin(), bad.output.end(), '\n'), 1) << bad.output;
  EXPECT_EQ(occurrences("bad_values.json: parameter"), 6u) << bad.output;
  EXPECT_EQ(occurrences("bad_values.json: unknown parameter"), 1u) << bad.output;
  const auto two = run_dspbr("params check " + kData + "bad_values.json " + kData + "generic_ok.json");
  EXPECT_EQ(two.status, 2);
  EXPECT_EQ(count_lines_with(two.output, "dspbr: error: "), 8) << two.output;  // 7 problems and the count
  EXPECT_EQ(run_dspbr("params check " + kData + "glass_ok.json --params " + kData + "cycle.json").status, 2);
  for (const char* f : {"unknown_material.json", "malformed_instance.json", "glass_ior_hidden.json"}) {
    const auto r = run_dspbr("params check " + kData + f);
    EXPECT_EQ(r.status, 2) << f;
    EXPECT_NE(r.output.find(f), std::string::npos) << r.output;
  }
  for (const char* f : {"cycle.json", "unknown_base.json", "bad_type.json", "malformed.json"}) {
    const auto r = run_dspbr(std::string("params list ") + kData + f);
    EXPECT_EQ(r.status, 2) << f;
    EXPECT_EQ(count_lines_with(r.output, "dspbr: error: "), 1) << r.output;
  }
  EXPECT_NE(run_dspbr("params show " + kOfficial + " unobtainium").status, 0);
}

// Without FILE, `params list` prints the built-in definitions: the shipped file's materials in
// file order, whatever the working folder.
TEST(ParamsCli, ListWithoutFileUsesTheBuiltInDefinitions) {
  const auto list = run_dspbr("params list --json", ::testing::TempDir());
  ASSERT_EQ(list.status, 0) << list.output;
  std::ifstream in(kOfficial);
  const auto raw = nlohmann::ordered_json::parse(in);
  std::vector<std::string> expected, listed;
  for (const auto& [id, _] : raw["materials"].items()) expected.push_back(id);
  const Json out = Json::parse(list.output);
  for (const auto& m : out["materials"]) listed.push_back(m["id"].get<std::string>());
  EXPECT_EQ(listed, expected);
}
