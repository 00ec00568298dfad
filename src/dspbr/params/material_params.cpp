#include "dspbr/params/material_params.h"

#include <cerrno>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "dspbr/io/decimal.h"
#include "dspbr/io/message.h"
#include "dspbr/nearest_name.h"
#include "dspbr/io/json_fields.h"

namespace dspbr {

namespace {

using Json = nlohmann::json;

struct Field {
  ParamKind kind;
  std::function<Json(const Material&)> get;
  std::function<void(Material&, const Json&)> set;
};

double json_number(const std::string& id, const Json& v) {
  if (v.is_number()) return v.get<double>();
  if (v.is_object() && v.size() == 1 && v.contains("infinity") && v["infinity"] == true)
    return std::numeric_limits<double>::infinity();
  throw std::invalid_argument("parameter '" + id + "' expects a number, got " + json_fields::quoted(v));
}

Json number_json(double x) {
  if (std::isinf(x) && x > 0) return Json{{"infinity", true}};
  return x;
}

std::array<double, 3> json_triple(const std::string& id, const Json& v) {
  if (!v.is_array() || v.size() != 3)
    throw std::invalid_argument("parameter '" + id + "' expects an array of 3 numbers, got " + json_fields::quoted(v));
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i) out[i] = json_number(id, v[i]);
  return out;
}

const std::map<std::string, Field>& fields() {
  static const std::map<std::string, Field> table = [] {
    std::map<std::string, Field> t;
    auto add_float = [&](const char* id, double Material::*mem) {
      t[id] = {ParamKind::Float, [mem](const Material& m) { return number_json(m.*mem); },
               [mem, id](Material& m, const Json& v) { m.*mem = json_number(id, v); }};
    };
    auto add_color = [&](const char* id, Rgb Material::*mem) {
      t[id] = {ParamKind::Color,
               [mem](const Material& m) { return Json::array({(m.*mem).r, (m.*mem).g, (m.*mem).b}); },
               [mem, id](Material& m, const Json& v) {
                 // A colour is one number (grey) or three, in files as on the command line.
                 if (v.is_number()) {
                   const double g = json_number(id, v);
                   m.*mem = Rgb(g, g, g);
                   return;
                 }
                 if (!v.is_array() || v.size() != 3)
                   throw std::invalid_argument("parameter '" + std::string(id) +
                                               "' expects a number (grey) or an array of 3 numbers, got " + json_fields::quoted(v));
                 const auto a = json_triple(id, v);
                 m.*mem = Rgb(a[0], a[1], a[2]);
               }};
    };
    auto add_vec = [&](const char* id, Vec3 Material::*mem, ParamKind kind) {
      t[id] = {kind, [mem](const Material& m) { return Json::array({(m.*mem).x, (m.*mem).y, (m.*mem).z}); },
               [mem, id](Material& m, const Json& v) {
                 const auto a = json_triple(id, v);
                 m.*mem = Vec3(a[0], a[1], a[2]);
               }};
    };
    auto add_bool = [&](const char* id, bool Material::*mem) {
      t[id] = {ParamKind::Boolean, [mem](const Material& m) { return Json(m.*mem); },
               [mem, id](Material& m, const Json& v) {
                 if (!v.is_boolean())
                   throw std::invalid_argument(std::string("parameter '") + id + "' expects true or false, got " + json_fields::quoted(v));
                 m.*mem = v.get<bool>();
               }};
    };
    add_color("albedo", &Material::albedo);
    add_float("metallic", &Material::metallic);
    add_float("roughness", &Material::roughness);
    add_float("anisotropy", &Material::anisotropy);
    add_float("anisotropyRotation", &Material::anisotropyRotation);
    add_vec("normal", &Material::normal, ParamKind::Normal);
    add_vec("displacement", &Material::displacement, ParamKind::Vector);
    add_float("translucency", &Material::translucency);
    add_color("translucencyColor", &Material::translucencyColor);
    add_float("transparency", &Material::transparency);
    add_float("cutoutOpacity", &Material::cutoutOpacity);
    add_float("specular", &Material::specular);
    add_color("specularTint", &Material::specularTint);
    add_float("thinFilm", &Material::thinFilm);
    add_float("thinFilmThickness", &Material::thinFilmThickness);
    add_float("thinFilmIor", &Material::thinFilmIor);
    add_color("sheenColor", &Material::sheenColor);
    add_float("sheenRoughness", &Material::sheenRoughness);
    add_float("flakeCoverage", &Material::flakeCoverage);
    add_color("flakeColor", &Material::flakeColor);
    add_float("flakeSize", &Material::flakeSize);
    add_float("flakeRoughness", &Material::flakeRoughness);
    add_float("flipFlop", &Material::flipFlop);
    add_color("flipFlopColor", &Material::flipFlopColor);
    add_float("clearcoat", &Material::clearcoat);
    add_float("clearcoatRoughness", &Material::clearcoatRoughness);
    add_vec("clearcoatNormal", &Material::clearcoatNormal, ParamKind::Normal);
    add_color("emissionColor", &Material::emissionColor);
    add_float("emissionValue", &Material::emissionValue);
    t["emissionMode"] = {
        ParamKind::Enum,
        [](const Material& m) {
          return Json(m.emissionMode == EmissionMode::LuminousPower ? "LUMINOUS_POWER" : "LUMINOUS_EMITTANCE");
        },
        [](Material& m, const Json& v) {
          if (v == "LUMINOUS_EMITTANCE") m.emissionMode = EmissionMode::LuminousEmittance;
          else if (v == "LUMINOUS_POWER") m.emissionMode = EmissionMode::LuminousPower;
          else throw std::invalid_argument("parameter 'emissionMode' expects \"LUMINOUS_EMITTANCE\" or \"LUMINOUS_POWER\", got " + json_fields::quoted(v));
        }};
    add_bool("emissionEnergyNormalization", &Material::emissionEnergyNormalization);
    add_bool("thinWalled", &Material::thinWalled);
    add_float("ior", &Material::ior);
    add_float("abbeNumber", &Material::abbeNumber);
    add_color("attenuationColor", &Material::attenuationColor);
    add_float("attenuationDistance", &Material::attenuationDistance);
    add_color("subsurfaceColor", &Material::subsurfaceColor);
    add_float("subsurfaceAnisotropy", &Material::subsurfaceAnisotropy);
    return t;
  }();
  return table;
}

const Field& field(const std::string& id) {
  const auto it = fields().find(id);
  if (it == fields().end()) {
    throw std::invalid_argument("unknown material parameter '" + id + "'" + did_you_mean(id, material_parameter_ids()));
  }
  return it->second;
}

}  // namespace

const std::vector<std::string>& material_parameter_ids() {
  static const std::vector<std::string> ids{
      "albedo", "metallic", "roughness", "anisotropy", "anisotropyRotation", "normal", "displacement",
      "translucency", "translucencyColor", "transparency", "cutoutOpacity", "specular", "specularTint",
      "thinFilm", "thinFilmThickness", "thinFilmIor", "sheenColor", "sheenRoughness", "flakeCoverage",
      "flakeColor", "flakeSize", "flakeRoughness", "flipFlop", "flipFlopColor", "clearcoat",
      "clearcoatRoughness", "clearcoatNormal", "emissionColor", "emissionValue", "emissionMode",
      "emissionEnergyNormalization", "thinWalled", "ior", "abbeNumber", "attenuationColor",
      "attenuationDistance", "subsurfaceColor", "subsurfaceAnisotropy"};
  return ids;
}

ParamKind material_parameter_kind(const std::string& id) { return field(id).kind; }

void set_material_parameter(Material& m, const std::string& id, const Json& value) { field(id).set(m, value); }

Json get_material_parameter(const Material& m, const std::string& id) { return field(id).get(m); }

Json parse_parameter_text(const std::string& id, const std::string& text) {
  auto number = [&](const std::string& s) -> Json {
    if (s == "inf" || s == "+inf" || s == "infinity") return Json{{"infinity", true}};
    // The one number grammar (decimal.h); a value too small for a normal double is kept
    // (subnormal or 0), one beyond its range refused.
    const std::string q = "parameter '" + id + "': '" + quote_input(s) + "' ";
    const Decimal x = parse_decimal(s);
    if (x.status == Decimal::NotANumber) throw std::invalid_argument(q + "is not a number");
    if (x.status == Decimal::OutOfRange) throw std::invalid_argument(q + "is beyond the range of a double");
    return x.value;
  };
  switch (material_parameter_kind(id)) {
    case ParamKind::Float: return number(text);
    case ParamKind::Color:
    case ParamKind::Normal:
    case ParamKind::Vector: {
      Json arr = Json::array();
      std::stringstream ss(text);
      std::string part;
      while (std::getline(ss, part, ',')) arr.push_back(number(part));
      const bool colour = material_parameter_kind(id) == ParamKind::Color;
      if (colour && arr.size() == 1) return arr[0];  // "0.5": grey, as in files
      if (arr.size() != 3)
        throw std::invalid_argument("parameter '" + id + "' expects " +
                                    (colour ? "one number (grey) or 3 comma-separated numbers (r,g,b)"
                                            : "3 comma-separated numbers (x,y,z)") +
                                    ", got '" + text + "'");
      return arr;
    }
    case ParamKind::Boolean:
      if (text == "true" || text == "1") return true;
      if (text == "false" || text == "0") return false;
      throw std::invalid_argument("parameter '" + id + "' expects true or false, got '" + text + "'");
    case ParamKind::Enum: return text;
  }
  return text;
}

}  // namespace dspbr
