#include "dspbr/params/material_instance.h"

#include "dspbr/limits.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "dspbr/io/read_file.h"
#include "dspbr/nearest_name.h"
#include "dspbr/params/material_params.h"
#include "dspbr/params/param_defs.h"
#include "dspbr/io/json_fields.h"
#include "dspbr/io/message.h"

namespace dspbr {

namespace {

using Json = nlohmann::json;

bool read_number(const Json& v, double& out) {
  if (v.is_number()) return out = v.get<double>(), true;
  if (v.is_object() && v.size() == 1) {
    if (v.contains("infinity") && v["infinity"] == true) return out = std::numeric_limits<double>::infinity(), true;
    if (v.contains("-infinity") && v["-infinity"] == true) return out = -std::numeric_limits<double>::infinity(), true;
  }
  return false;
}

std::string show(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return Json(x).dump();
}

// The problems of one value against its definition (empty when valid).
void check_value(const ParamDef& d, const Json& v, std::vector<std::string>& problems) {
  const std::string p = "parameter '" + d.id + "'";
  switch (d.type) {
    case ParamKind::Float: {
      double x = 0, lo = 0, hi = 0;
      if (!read_number(v, x)) {
        problems.push_back(p + ": wrong type, expected a number (float), got " + json_fields::quoted(v));
        return;
      }
      read_number(d.min, lo);
      read_number(d.max, hi);
      if (x < lo || x > hi)
        problems.push_back(p + ": value " + show(x) + " is out of range [" + show(lo) + ", " + show(hi) + "]");
      return;
    }
    case ParamKind::Color:
    case ParamKind::Normal:
    case ParamKind::Vector: {
      const char* type = param_type_name(d.type);
      // A colour is one number (grey) or three, as on the command line.
      if (d.type == ParamKind::Color && v.is_number()) {
        check_value(d, Json::array({v, v, v}), problems);
        return;
      }
      if (!v.is_array()) {
        problems.push_back(p + ": wrong type, expected " +
                           (d.type == ParamKind::Color ? "a number (grey) or " : "") + "an array of 3 numbers (" +
                           type + "), got " + json_fields::quoted(v));
        return;
      }
      if (v.size() != 3) {
        problems.push_back(p + ": wrong length, expected 3 numbers (" + type + "), got " + std::to_string(v.size()));
        return;
      }
      double c[3];
      for (int i = 0; i < 3; ++i)
        if (!read_number(v[i], c[i])) {
          problems.push_back(p + ": wrong type, component " + std::to_string(i) + " is not a number: " + json_fields::quoted(v[i]));
          return;
        }
      if (d.type == ParamKind::Normal) {
        // 1e-3: tolerance for unit length of a normal written with a few decimals.
        const double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (!(std::abs(len - 1.0) <= 1e-3))
          problems.push_back(p + ": normal " + json_fields::quoted(v) + " must have unit length (has " + show(len) + ")");
        return;
      }
      for (int i = 0; i < 3; ++i) {
        double lo = 0, hi = 0;
        read_number(d.min[i], lo);
        read_number(d.max[i], hi);
        if (c[i] < lo || c[i] > hi) {
          problems.push_back(p + ": value " + json_fields::quoted(v) + " is out of range [" + json_fields::quoted(d.min) + ", " + json_fields::quoted(d.max) + "]");
          return;
        }
      }
      return;
    }
    case ParamKind::Boolean:
      if (!v.is_boolean()) problems.push_back(p + ": wrong type, expected true or false (boolean), got " + json_fields::quoted(v));
      return;
    case ParamKind::Enum: {
      std::string allowed;
      for (const auto& e : d.enum_values) allowed += (allowed.empty() ? "" : ", ") + e;
      if (!v.is_string()) {
        problems.push_back(p + ": wrong type, expected one of " + allowed + " (enum string), got " + json_fields::quoted(v));
        return;
      }
      for (const auto& e : d.enum_values)
        if (v.get<std::string>() == e) return;
      problems.push_back(p + ": value " + json_fields::quoted(v) + " is not one of " + allowed);
      return;
    }
  }
}

}  // namespace

ParamDefs default_param_defs() {
  if (const char* env = std::getenv("DSPBR_PARAMS"); env && *env) {
    try {
      return ParamDefs::load(env);
    } catch (const std::runtime_error& e) {  // the file's problem, said to come from the variable
      throw std::runtime_error(std::string("$DSPBR_PARAMS: ") + e.what());
    }
  }
  return ParamDefs::builtin();
}

std::vector<std::string> check_material_instance(const ParamDefs& defs, const Json& instance) {
  std::vector<std::string> problems;
  if (!instance.is_object()) {
    problems.push_back("expected a JSON object {\"material\": \"<type>\", \"values\": {...}}");
    return problems;
  }
  for (const auto& [key, _] : instance.items())
    if (key != "material" && key != "values")
      problems.push_back("unknown key '" + quote_input(key) + "' (an instance has only \"material\" and \"values\")");
  if (instance.contains("material") && !instance["material"].is_string()) {
    problems.push_back("\"material\" must be a string (the material type, e.g. \"glass\"), got " +
                       json_fields::quoted(instance["material"]));
    return problems;
  }
  if (!instance.contains("material")) {
    problems.push_back("missing \"material\": the material type as a string, e.g. \"glass\"");
    return problems;
  }
  const std::string type = instance["material"].get<std::string>();
  if (!defs.has_material(type)) {
    try {
      defs.material(type);
    } catch (const std::exception& e) {
      problems.push_back(e.what());
    }
    return problems;
  }
  const MaterialDef& m = defs.material(type);
  if (!instance.contains("values")) return problems;  // all defaults
  const Json& values = instance["values"];
  if (!values.is_object()) {
    problems.push_back("\"values\" must be an object {\"<parameter id>\": value, ...}");
    return problems;
  }
  for (const auto& [id, v] : values.items()) {
    const ParamDef* d = m.find(id);
    if (!d) {
      std::vector<std::string> ids;
      for (const ParamDef& p : m.parameters)
        if (!p.hidden) ids.push_back(p.id);
      problems.push_back("unknown parameter " + in_quotes(id) + " for material " + in_quotes(type) + did_you_mean(id, ids));
      continue;
    }
    if (d->hidden) {
      problems.push_back("parameter " + in_quotes(id) + " is hidden in material " + in_quotes(type) + " and must not be set");
      continue;
    }
    check_value(*d, v, problems);
  }
  return problems;
}

Material material_from_instance(const ParamDefs& defs, const Json& instance) {
  const auto problems = check_material_instance(defs, instance);
  if (!problems.empty()) {
    std::string all;
    for (const auto& p : problems) all += (all.empty() ? "" : "; ") + p;
    throw std::runtime_error(all);
  }
  const MaterialDef& m = defs.material(instance["material"].get<std::string>());
  Material out;
  auto apply = [&](const std::string& id, const Json& v) {
    try {
      set_material_parameter(out, id, v);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error("material " + in_quotes(m.id) + ": " + e.what() + " (no counterpart in the reference BSDF)");
    }
  };
  for (const auto& p : m.parameters) apply(p.id, p.default_value);
  if (instance.contains("values"))
    for (const auto& [id, v] : instance["values"].items()) apply(id, v);
  return out;
}

Material load_material_instance(const std::string& path) {
  const Json doc = read_json_file(path, "material instance file", limits::kDocumentBytes);
  const ParamDefs defs = default_param_defs();
  try {
    return material_from_instance(defs, doc);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}  // namespace dspbr
