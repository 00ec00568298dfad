#include "dspbr/params/param_defs.h"

#include "dspbr/io/message.h"
#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"
#include "dspbr/io/json_fields.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace dspbr {

namespace {

using Json = nlohmann::json;
constexpr double kInf = std::numeric_limits<double>::infinity();

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw std::runtime_error(source + ": " + what);
}

// A number in the file's conventions: plain number, {"infinity": true} (+inf, spec appendix
// "Types") or {"-infinity": true} (our spelling of -inf for type-derived minimums).
bool read_number(const Json& v, double& out) {
  if (v.is_number()) {
    out = v.get<double>();
    return true;
  }
  if (v.is_object() && v.size() == 1) {
    if (v.contains("infinity") && v["infinity"] == true) return out = kInf, true;
    if (v.contains("-infinity") && v["-infinity"] == true) return out = -kInf, true;
  }
  return false;
}

Json number_json(double x) {
  if (std::isinf(x)) return x > 0 ? Json{{"infinity", true}} : Json{{"-infinity", true}};
  return x;
}

bool parse_type(const std::string& s, ParamKind& kind) {
  static const std::pair<const char*, ParamKind> types[] = {
      {"float", ParamKind::Float},   {"color", ParamKind::Color},     {"normal", ParamKind::Normal},
      {"vector", ParamKind::Vector}, {"boolean", ParamKind::Boolean}, {"enum", ParamKind::Enum}};
  for (const auto& [name, k] : types)
    if (s == name) return kind = k, true;
  return false;
}

// Recursive merge (spec appendix "Inheritance"): objects merge key by key, derived values
// overwrite base values, anything else is replaced.
void merge_into(Json& base, const Json& derived) {
  for (const auto& [key, value] : derived.items()) {
    if (value.is_object() && base.contains(key) && base[key].is_object()) merge_into(base[key], value);
    else base[key] = value;
  }
}

// Replaces every {"$ref": "#/json/pointer"} (as used by params-2025x.json's plastic
// translucencyColor default) by its target in the resolved document. Bounded (limits.h): nested
// references, the nesting depth of the result and the number of values it holds.
struct RefResolver {
  const Json& doc;
  const std::string& source;
  std::size_t values = 0;

  void resolve(Json& node, int ref_depth = 0, int level = 0) {
    if (level > limits::kJsonDepth)
      fail(source, "nested deeper than " + std::to_string(limits::kJsonDepth) + " levels once \"$ref\"s are resolved");
    if (++values > limits::kResolvedJsonValues)
      fail(source, "more than " + std::to_string(limits::kResolvedJsonValues) +
                       " JSON values once inheritance and \"$ref\"s are resolved (references or bases that multiply)");
    if (node.is_object() && node.size() == 1 && node.contains("$ref")) {
      if (ref_depth >= limits::kRefDepth)
        fail(source, "circular or too deep \"$ref\" chain (more than " + std::to_string(limits::kRefDepth) + " nested)");
      const Json& ref = node["$ref"];
      if (!ref.is_string() || ref.get<std::string>().rfind("#/", 0) != 0)
        fail(source, "\"$ref\" must be a string \"#/...\" pointing into the same file, got " + json_fields::quoted(ref));
      const std::string pointer = ref.get<std::string>().substr(1);
      Json target;
      try {
        target = doc.at(Json::json_pointer(pointer));
      } catch (const std::exception&) {
        fail(source, "\"$ref\" " + json_fields::quoted(ref) + " points to nothing");
      }
      --values;  // the reference itself is replaced
      resolve(target, ref_depth + 1, level);
      node = std::move(target);
      return;
    }
    if (node.is_structured())
      for (auto& child : node) resolve(child, ref_depth, level + 1);
  }
};

// The JSON values of a document: itself and every value inside it, at any depth.
std::size_t json_value_count(const Json& j) {
  std::size_t n = 1;
  if (j.is_structured())
    for (const auto& child : j) n += json_value_count(child);
  return n;
}

struct Resolver {
  const Json& materials;
  const std::string& source;
  std::map<std::string, Json> done;
  std::map<std::string, std::vector<std::string>> chains;
  std::size_t values = 0;  // of the materials merged so far: limits::kResolvedJsonValues, counted
                           // as each is merged (a base copied into 40,000 materials is refused
                           // at the material that crosses the limit, not after all are built)

  const Json& resolve(const std::string& id, std::vector<std::string>& stack) {
    if (auto it = done.find(id); it != done.end()) return it->second;
    if (std::find(stack.begin(), stack.end(), id) != stack.end()) {
      std::string cycle;
      for (const auto& s : stack) cycle += s + " -> ";
      fail(source, "inheritance cycle: " + cycle + id);
    }
    const Json& own = materials.at(id);
    if (!own.is_object()) fail(source, "material '" + id + "' must be a JSON object");
    auto too_long = [&](std::size_t bases) {
      if (bases >= std::size_t(limits::kInheritanceDepth))
        fail(source, "material '" + (stack.empty() ? id : stack.front()) + "': inheritance chain longer than " +
                         std::to_string(limits::kInheritanceDepth) + " materials");
    };
    too_long(stack.size());  // bounds the recursion
    Json merged = Json::object();
    std::vector<std::string> chain;
    if (own.contains("inherits")) {
      const Json& base = own["inherits"];
      if (!base.is_string()) fail(source, "material '" + id + "': \"inherits\" must be a material id string");
      const std::string base_id = base.get<std::string>();
      if (!materials.contains(base_id))
        fail(source, "material '" + id + "' inherits from unknown material '" + base_id + "'");
      stack.push_back(id);
      merged = resolve(base_id, stack);
      stack.pop_back();
      chain.push_back(base_id);
      const auto& base_chain = chains.at(base_id);
      chain.insert(chain.end(), base_chain.begin(), base_chain.end());
      too_long(chain.size());  // bases resolved earlier are not on the stack
    }
    merge_into(merged, own);
    values += json_value_count(merged);
    if (values > limits::kResolvedJsonValues)
      fail(source, "more than " + std::to_string(limits::kResolvedJsonValues) +
                       " JSON values once inheritance is merged, at material '" + id +
                       "' (bases copied into many materials)");
    chains[id] = chain;
    return done[id] = std::move(merged);
  }
};

// Reads a min/max/default value of the given type; `what` names it in messages.
Json typed_value(const Json& v, ParamKind type, const std::string& what, const std::string& source,
                 const std::vector<std::string>& enum_values = {}) {
  double x = 0;
  switch (type) {
    case ParamKind::Float:
      if (!read_number(v, x)) fail(source, what + " must be a number or {\"infinity\": true}, got " + json_fields::quoted(v));
      return number_json(x);
    case ParamKind::Color:
    case ParamKind::Normal:
    case ParamKind::Vector: {
      if (!v.is_array() || v.size() != 3) fail(source, what + " must be an array of 3 numbers, got " + json_fields::quoted(v));
      Json out = Json::array();
      for (const auto& c : v) {
        if (!read_number(c, x)) fail(source, what + " must be an array of 3 numbers, got " + json_fields::quoted(v));
        out.push_back(number_json(x));
      }
      return out;
    }
    case ParamKind::Boolean:
      if (!v.is_boolean()) fail(source, what + " must be true or false, got " + json_fields::quoted(v));
      return v;
    case ParamKind::Enum:
      if (!v.is_string() || std::find(enum_values.begin(), enum_values.end(), v.get<std::string>()) == enum_values.end())
        fail(source, what + " must be one of the parameter's \"enum\" values, got " + json_fields::quoted(v));
      return v;
  }
  return v;
}

ParamDef make_param(const std::string& mat, const std::string& id, const Json& p, const std::string& source) {
  const std::string where = "material '" + mat + "', parameter '" + id + "'";
  if (!p.is_object()) fail(source, where + " must be a JSON object");
  ParamDef d;
  d.id = id;
  d.resolved = p;
  if (!p.contains("type") || !p["type"].is_string())
    fail(source, where + " has no \"type\" (float, color, normal, vector, boolean or enum)");
  if (!parse_type(p["type"].get<std::string>(), d.type))
    fail(source, where + " has unknown type " + json_fields::quoted(p["type"]) + " (expected float, color, normal, vector, boolean or enum)");
  if (p.contains("name")) {
    if (!p["name"].is_string()) fail(source, where + ": \"name\" must be a string");
    d.name = p["name"].get<std::string>();
  }
  auto flag = [&](const char* key) {
    if (!p.contains(key)) return false;
    if (!p[key].is_boolean()) fail(source, where + ": \"" + key + "\" must be true or false");
    return p[key].get<bool>();
  };
  d.uniform = flag("uniform");
  d.hidden = flag("hidden");
  d.ui_order = -1;
  if (p.contains("uiOrder")) {
    const Json& order = p["uiOrder"];
    if (!order.is_number_integer() || (order.is_number_unsigned() ? order.get<std::uint64_t>() > INT_MAX
                                                                  : order.get<std::int64_t>() < 0))
      fail(source, where + ": \"uiOrder\" must be an integer from 0 to " + std::to_string(INT_MAX) + ", got " +
                       json_fields::quoted(order));
    d.ui_order = order.get<int>();
  }
  if (p.contains("group")) {
    if (!p["group"].is_string()) fail(source, where + ": \"group\" must be a string");
    d.group = p["group"].get<std::string>();
  }
  if (d.type == ParamKind::Enum) {
    if (!p.contains("enum") || !p["enum"].is_array() || p["enum"].empty())
      fail(source, where + " of type enum needs a non-empty \"enum\" array of strings");
    for (const auto& e : p["enum"]) {
      if (!e.is_string()) fail(source, where + ": \"enum\" values must be strings");
      d.enum_values.push_back(e.get<std::string>());
    }
  }
  // Type-derived values (spec appendix "Types", table json-types). The enum's default is "n/a" in
  // the spec; we take the first listed value so that every parameter has a default.
  const Json inf = number_json(kInf), minus_inf = number_json(-kInf);
  Json def, lo, hi;
  switch (d.type) {
    case ParamKind::Float: def = 0.0, lo = minus_inf, hi = inf; break;
    case ParamKind::Color: def = Json::array({0.0, 0.0, 0.0}), lo = def, hi = Json::array({inf, inf, inf}); break;
    case ParamKind::Normal: def = Json::array({0.0, 0.0, 1.0}); break;
    case ParamKind::Vector:
      def = Json::array({0.0, 0.0, 0.0}), lo = Json::array({minus_inf, minus_inf, minus_inf}),
      hi = Json::array({inf, inf, inf});
      break;
    case ParamKind::Boolean: def = false; break;
    case ParamKind::Enum: def = d.enum_values.front(); break;
  }
  const bool ranged = d.type == ParamKind::Float || d.type == ParamKind::Color || d.type == ParamKind::Vector;
  for (const char* key : {"min", "max"})
    if (p.contains(key) && !ranged)
      fail(source, where + ": type " + p["type"].get<std::string>() + " has no \"" + key + "\"");
  d.default_value = p.contains("default") ? typed_value(p["default"], d.type, where + " default", source, d.enum_values) : def;
  d.min = p.contains("min") ? typed_value(p["min"], d.type, where + " min", source) : lo;
  d.max = p.contains("max") ? typed_value(p["max"], d.type, where + " max", source) : hi;
  // The default must lie in [min, max]; a normal's default must have unit length.
  if (ranged) {
    const bool scalar = d.type == ParamKind::Float;
    for (int i = 0; i < (scalar ? 1 : 3); ++i) {
      double v = 0, a = 0, b = 0;
      read_number(scalar ? d.default_value : d.default_value[i], v);
      read_number(scalar ? d.min : d.min[i], a);
      read_number(scalar ? d.max : d.max[i], b);
      if (a > b) fail(source, where + ": min " + json_fields::quoted(d.min) + " exceeds max " + json_fields::quoted(d.max));
      if (v < a || v > b)
        fail(source, where + ": default " + json_fields::quoted(d.default_value) + " lies outside [" + json_fields::quoted(d.min) + ", " + json_fields::quoted(d.max) + "]");
    }
  }
  if (d.type == ParamKind::Normal) {
    double v[3];
    for (int i = 0; i < 3; ++i) read_number(d.default_value[i], v[i]);
    // 1e-3: tolerance for unit length of a normal written with a few decimals.
    if (std::abs(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1.0) > 1e-3)
      fail(source, where + ": default normal " + json_fields::quoted(d.default_value) + " is not unit length");
  }
  return d;
}

void sort_ui_order(std::vector<ParamDef>& params) {
  // Group rank: '' first (spec appendix "Format"), then named groups by their smallest uiOrder.
  std::map<std::string, long> group_first;
  for (const auto& p : params) {
    const long order = p.ui_order < 0 ? std::numeric_limits<int>::max() : p.ui_order;
    auto it = group_first.find(p.group);
    if (it == group_first.end()) group_first[p.group] = order;
    else it->second = std::min(it->second, order);
  }
  auto key = [&](const ParamDef& p) {
    const long rank = p.group.empty() ? -1 : group_first[p.group];
    const long order = p.ui_order < 0 ? std::numeric_limits<int>::max() : p.ui_order;
    return std::make_tuple(rank, p.group, order, p.id);
  };
  std::stable_sort(params.begin(), params.end(), [&](const ParamDef& a, const ParamDef& b) { return key(a) < key(b); });
}

}  // namespace

const ParamDef* MaterialDef::find(const std::string& param_id) const {
  for (const auto& p : parameters)
    if (p.id == param_id) return &p;
  return nullptr;
}

const char* param_type_name(ParamKind kind) {
  switch (kind) {
    case ParamKind::Float: return "float";
    case ParamKind::Color: return "color";
    case ParamKind::Normal: return "normal";
    case ParamKind::Vector: return "vector";
    case ParamKind::Boolean: return "boolean";
    case ParamKind::Enum: return "enum";
  }
  return "?";
}

ParamDefs ParamDefs::load(const std::string& path) {
  return from_json(read_json_file<nlohmann::ordered_json>(path, "parameter definition file", limits::kDocumentBytes), path);
}

// Defined in the source CMake generates from data/dspbr/params-2025x.json.
std::string_view params_2025x_json();

const ParamDefs& ParamDefs::builtin() {
  static const ParamDefs defs = [] {
    const std::string_view text = params_2025x_json();
    return from_json(nlohmann::ordered_json::parse(text.begin(), text.end()), "built-in params-2025x.json");
  }();
  return defs;
}

ParamDefs ParamDefs::from_json(const Json& doc, const std::string& source) {
  return from_json(nlohmann::ordered_json::parse(doc.dump()), source);
}

ParamDefs ParamDefs::from_json(const nlohmann::ordered_json& ordered, const std::string& source) {
  const Json doc = Json::parse(ordered.dump());
  if (!doc.is_object() || !doc.contains("materials") || !doc["materials"].is_object())
    fail(source, "expected a JSON object with a \"materials\" object");
  const Json& materials = doc["materials"];
  ParamDefs defs;
  defs.source_ = source;
  Resolver resolver{materials, source, {}, {}, 0};
  Json resolved_doc = {{"materials", Json::object()}};
  for (const auto& [id, _] : materials.items()) {
    std::vector<std::string> stack;
    resolved_doc["materials"][id] = resolver.resolve(id, stack);
  }
  const Json lookup = resolved_doc;
  RefResolver{lookup, source}.resolve(resolved_doc);
  // nlohmann::json orders object keys alphabetically; `ordered` keeps the file's order.
  for (const auto& [id, _] : ordered["materials"].items()) {
    const Json& m = resolved_doc["materials"][id];
    MaterialDef def;
    def.id = id;
    def.inherits = resolver.chains.at(id);
    if (m.contains("name")) {
      if (!m["name"].is_string()) fail(source, "material '" + id + "': \"name\" must be a string");
      def.name = m["name"].get<std::string>();
    }
    if (m.contains("parameters")) {
      if (!m["parameters"].is_object()) fail(source, "material '" + id + "': \"parameters\" must be an object");
      for (const auto& [pid, p] : m["parameters"].items()) def.parameters.push_back(make_param(id, pid, p, source));
    }
    sort_ui_order(def.parameters);
    defs.order_.push_back(id);
    defs.materials_[id] = std::move(def);
  }
  return defs;
}

std::vector<std::string> ParamDefs::material_ids() const { return order_; }

bool ParamDefs::has_material(const std::string& id) const { return materials_.count(id) > 0; }

const MaterialDef& ParamDefs::material(const std::string& id) const {
  const auto it = materials_.find(id);
  if (it == materials_.end()) {
    std::string known;
    for (const auto& m : order_) known += (known.empty() ? "" : ", ") + quote_input(m);
    throw std::invalid_argument("unknown material " + in_quotes(id) + " (" + source_ + " defines: " + known + ")");
  }
  return it->second;
}

nlohmann::ordered_json material_def_to_json(const MaterialDef& m) {
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const auto& p : m.parameters) {
    nlohmann::ordered_json j;
    j["name"] = p.name;
    j["type"] = param_type_name(p.type);
    j["default"] = p.default_value;
    j["min"] = p.min;
    j["max"] = p.max;
    j["uniform"] = p.uniform;
    j["hidden"] = p.hidden;
    j["group"] = p.group;
    j["uiOrder"] = p.ui_order < 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(p.ui_order);
    if (p.type == ParamKind::Enum) j["enum"] = p.enum_values;
    for (const auto& [key, value] : p.resolved.items())  // other properties, as merged
      if (!j.contains(key)) j[key] = value;
    params[p.id] = j;
  }
  return {{"parameters", params}};
}

}  // namespace dspbr
