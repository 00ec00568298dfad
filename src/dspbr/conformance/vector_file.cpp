#include "dspbr/conformance/vector_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <vector>

#include "dspbr/component.h"
#include "dspbr/conformance/vector_set.h"
#include "dspbr/io/json_fields.h"
#include "dspbr/io/json_values.h"
#include "dspbr/io/message.h"
#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"
#include "dspbr/nearest_name.h"

namespace dspbr::conformance {

namespace {

using OJson = nlohmann::ordered_json;
using Json = nlohmann::json;
namespace jf = json_fields;

OJson tolerance_json(const Tolerance& t) { return OJson{{"abs", t.abs}, {"rel", t.rel}}; }
OJson rgb(const Rgb& c) { return OJson::array({c.r, c.g, c.b}); }
OJson vec(const Vec3& v) { return OJson::array({v.x, v.y, v.z}); }

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// A CSV field: quoted (quotes doubled) when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

Tolerance read_tolerance(const Json& obj, const std::string& key, const std::string& where) {
  const Json& t = jf::object_member(obj, key, where);
  const std::string w = jf::member_path(where, key);
  Tolerance out{jf::number_member(t, "abs", w), jf::number_member(t, "rel", w)};
  if (out.abs < 0 || out.rel < 0) throw std::runtime_error(w + " must not be negative");
  return out;
}


Vec3 read_direction(const Json& obj, const std::string& key, const std::string& where) {
  const Rgb x = read_rgb(obj, key, where);
  const Vec3 d{x.r, x.g, x.b};
  if (std::abs(length(d) - 1) > 1e-9) throw std::runtime_error(jf::member_path(where, key) + " must be a unit vector");
  return d;
}

// The members a vector may have (vector.h); any other is refused, as a misspelt optional member
// ("albdo") would otherwise go unjudged.
const std::vector<std::string> kVectorMembers = {"id", "group", "components", "material", "gltf_material", "options",
                                                 "v", "l", "f_cos", "tolerance", "pdf", "pdf_tolerance", "albedo",
                                                 "albedo_tolerance", "emission", "emission_tolerance", "delta",
                                                 "delta_tolerance"};

Vector read_vector(const Json& j, const std::string& where) {
  Vector v;
  v.id = jf::string_member(j, "id", where);
  if (v.id.empty()) throw std::runtime_error(jf::member_path(where, "id") + " must not be empty");
  const std::string w = where + " (id " + in_quotes(v.id) + ")";
  for (const auto& [key, _] : j.items())
    if (std::find(kVectorMembers.begin(), kVectorMembers.end(), key) == kVectorMembers.end())
      throw std::runtime_error(w + ": unknown member " + in_quotes(key) + did_you_mean(key, kVectorMembers));
  v.group = jf::string_member(j, "group", w);
  const Json& comps = jf::array_member(j, "components", w);
  for (std::size_t i = 0; i < comps.size(); ++i) {
    if (!comps[i].is_string())
      throw std::runtime_error(jf::index_path(jf::member_path(w, "components"), i) + " must be a string");
    v.components.push_back(comps[i].get<std::string>());
  }
  try {
    parse_component_names(v.components);  // each a component of the model
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(jf::member_path(w, "components") + ": " + e.what());
  }
  v.material = OJson(jf::object_member(j, "material", w));
  try {
    vector_material(v);  // a valid instance of a built-in material, whatever the checker's options
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(jf::member_path(w, "material") + ": " + e.what());
  }
  if (j.contains("gltf_material")) v.gltf_material = OJson(jf::object_member(j, "gltf_material", w));
  if (j.contains("options")) {
    v.options = OJson(jf::object_member(j, "options", w));
    try {
      vector_options(v);  // known options with valid values
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(w + ": " + e.what());
    }
  }
  v.v = read_direction(j, "v", w);
  v.l = read_direction(j, "l", w);
  v.f_cos = read_rgb(j, "f_cos", w);
  v.tolerance = read_tolerance(j, "tolerance", w);
  v.pdf = jf::number_member(j, "pdf", w);
  v.pdf_tolerance = read_tolerance(j, "pdf_tolerance", w);
  if (j.contains("albedo")) {
    v.albedo = read_rgb(j, "albedo", w);
    v.albedo_tolerance = read_tolerance(j, "albedo_tolerance", w);
  }
  if (j.contains("emission")) {
    v.emission = read_rgb(j, "emission", w);
    v.emission_tolerance = read_tolerance(j, "emission_tolerance", w);
  }
  if (j.contains("delta")) {
    const Json& d = jf::array_member(j, "delta", w);
    for (std::size_t i = 0; i < d.size(); ++i) {
      const std::string wi = jf::index_path(jf::member_path(w, "delta"), i);
      v.delta.push_back({read_direction(d[i], "l", wi), read_rgb(d[i], "value", wi)});
    }
    v.delta_tolerance = read_tolerance(j, "delta_tolerance", w);
  }
  return v;
}

}  // namespace

Rgb read_rgb(const Json& obj, const std::string& key, const std::string& where) {
  const Json& a = jf::member(obj, key, where);
  if (!a.is_array() || a.size() != 3)
    throw std::runtime_error(jf::member_path(where, key) + " must be an array of 3 numbers, got " + jf::excerpt(a));
  const auto x = jf::numbers_member(obj, key, where, 3);
  return {x[0], x[1], x[2]};
}

bool Tolerance::admits(double result, double expected) const { return ratio(result, expected) <= 1; }

double Tolerance::ratio(double result, double expected) const {
  const double bound = abs + rel * std::abs(expected);
  const double err = std::abs(result - expected);
  if (!(bound > 0)) return err == 0 ? 0 : HUGE_VAL;
  return err / bound;
}

OJson vector_json(const Vector& v) {
  OJson j;
  j["id"] = v.id;
  j["group"] = v.group;
  j["components"] = v.components;
  j["material"] = v.material;
  if (!v.gltf_material.is_null()) j["gltf_material"] = v.gltf_material;
  if (!v.options.is_null()) j["options"] = v.options;
  j["v"] = vec(v.v);
  j["l"] = vec(v.l);
  j["f_cos"] = rgb(v.f_cos);
  j["tolerance"] = tolerance_json(v.tolerance);
  j["pdf"] = v.pdf;
  j["pdf_tolerance"] = tolerance_json(v.pdf_tolerance);
  if (v.albedo) {
    j["albedo"] = rgb(*v.albedo);
    j["albedo_tolerance"] = tolerance_json(v.albedo_tolerance);
  }
  if (v.emission) {
    j["emission"] = rgb(*v.emission);
    j["emission_tolerance"] = tolerance_json(v.emission_tolerance);
  }
  if (!v.delta.empty()) {
    OJson d = OJson::array();
    for (const DeltaExpectation& x : v.delta) d.push_back(OJson{{"l", vec(x.l)}, {"value", rgb(x.value)}});
    j["delta"] = d;
    j["delta_tolerance"] = tolerance_json(v.delta_tolerance);
  }
  return j;
}

OJson vectors_document(const std::vector<Vector>& vectors, const OJson& provenance) {
  OJson doc;
  doc["format"] = kFormat;
  doc["version"] = kFormatVersion;
  doc["provenance"] = provenance;
  OJson arr = OJson::array();
  for (const Vector& v : vectors) arr.push_back(vector_json(v));
  doc["vectors"] = std::move(arr);
  return doc;
}

std::string vectors_csv(const std::vector<Vector>& vectors) {
  std::string out =
      "id,group,components,material,options,v_x,v_y,v_z,l_x,l_y,l_z,f_cos_r,f_cos_g,f_cos_b,tol_abs,tol_rel,pdf,pdf_tol_abs,"
      "pdf_tol_rel,albedo_r,albedo_g,albedo_b,albedo_tol_abs,albedo_tol_rel\n";
  for (const Vector& v : vectors) {
    std::string comps;
    for (const std::string& c : v.components) comps += (comps.empty() ? "" : ";") + c;
    std::string line = csv_field(v.id) + "," + csv_field(v.group) + "," + csv_field(comps) + "," + csv_field(v.material.dump()) + "," +
                       csv_field(v.options.is_null() ? std::string() : v.options.dump());
    for (double x : {v.v.x, v.v.y, v.v.z, v.l.x, v.l.y, v.l.z, v.f_cos.r, v.f_cos.g, v.f_cos.b, v.tolerance.abs,
                     v.tolerance.rel, v.pdf, v.pdf_tolerance.abs, v.pdf_tolerance.rel})
      line += "," + number(x);
    if (v.albedo) {
      for (double x : {v.albedo->r, v.albedo->g, v.albedo->b, v.albedo_tolerance.abs, v.albedo_tolerance.rel})
        line += "," + number(x);
    } else {
      line += ",,,,,";
    }
    out += line + "\n";
  }
  return out;
}

std::vector<Vector> vectors_from_json(const Json& doc, const std::string& path) {
  try {
    if (!doc.is_object() || !doc.contains("format") || doc["format"] != kFormat)
      throw std::runtime_error(std::string("not a conformance vector file (\"format\" must be \"") + kFormat + "\")");
    const long long version = jf::integer_member(doc, "version", "", 0, 1LL << 40);
    if (version != kFormatVersion)
      throw std::runtime_error("version " + std::to_string(version) + " is not supported (this dspbr reads version " +
                               std::to_string(kFormatVersion) + ")");
    const Json& arr = jf::array_member(doc, "vectors", "");
    std::vector<Vector> out;
    std::set<std::string> ids;
    for (std::size_t i = 0; i < arr.size(); ++i) {
      Vector v = read_vector(arr[i], jf::index_path("vectors", i));
      if (!ids.insert(v.id).second)
        throw std::runtime_error(jf::index_path("vectors", i) + ": duplicate id " + in_quotes(v.id));
      out.push_back(std::move(v));
    }
    if (out.empty()) throw std::runtime_error("\"vectors\" is empty");
    return out;
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

std::vector<Vector> read_vectors(const std::string& path) {
  return vectors_from_json(read_json_file(path, "conformance vector file", limits::kDocumentBytes), path);
}

}  // namespace dspbr::conformance
