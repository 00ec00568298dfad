// Parameter definition files in the spec's "Parameter JSON file format" (appendix), e.g.
// params-2025x.json: materials with typed parameters (float, color, normal, vector, boolean,
// enum), optional min/max/default derived from the type when absent, {"infinity": true} for +inf,
// uniform / hidden / uiOrder / group, and inheritance by recursive merge ("inherits").
#pragma once
#include <nlohmann/json.hpp>
#include <map>
#include <string>
#include <vector>

#include "dspbr/params/material_params.h"

namespace dspbr {

// One resolved parameter: everything inherited merged in and every type-derived value filled in.
// Numbers use the file's JSON conventions: +inf is {"infinity": true}; -inf (a type-derived
// minimum only) is {"-infinity": true}; min/max are null where the type has none (normal,
// boolean, enum).
struct ParamDef {
  std::string id;
  std::string name;     // display name ("" when the file gives none)
  ParamKind type = ParamKind::Float;
  nlohmann::json default_value;
  nlohmann::json min;   // number for float, array of 3 for color/vector, null for n/a
  nlohmann::json max;
  std::vector<std::string> enum_values;  // type enum only
  bool uniform = false;
  bool hidden = false;
  int ui_order = 0;
  std::string group;
  nlohmann::json resolved;  // the whole merged JSON object, incl. properties we do not interpret
};

struct MaterialDef {
  std::string id;
  std::string name;
  std::vector<std::string> inherits;  // base chain, nearest base first
  std::vector<ParamDef> parameters;   // in UI order: group '' first, then groups by their first
                                      // uiOrder, uiOrder within a group, ties by id
  const ParamDef* find(const std::string& param_id) const;  // nullptr when absent
};

class ParamDefs {
 public:
  // Reads and resolves a definition file. Throws std::runtime_error naming the file and the
  // problem for a missing, unreadable or non-JSON file (read_json_file), a missing "materials" object, an unknown parameter type, an
  // inheritance cycle or an unknown base, a malformed range/default, or a default out of range.
  static ParamDefs load(const std::string& path);
  // The definitions of data/dspbr/params-2025x.json, compiled into the library (parsed once;
  // source() is "built-in params-2025x.json"): no file is read at run time.
  static const ParamDefs& builtin();
  // Same from an already parsed document; `source` names it in messages.
  static ParamDefs from_json(const nlohmann::json& doc, const std::string& source);
  // Same, keeping the file's material order (nlohmann::json sorts keys).
  static ParamDefs from_json(const nlohmann::ordered_json& doc, const std::string& source);

  std::vector<std::string> material_ids() const;  // in file order
  bool has_material(const std::string& id) const;
  // Throws std::invalid_argument naming the known materials for an unknown id.
  const MaterialDef& material(const std::string& id) const;
  const std::string& source() const { return source_; }

 private:
  std::string source_;
  std::vector<std::string> order_;
  std::map<std::string, MaterialDef> materials_;
};

// Name of a ParamKind as written in the file ("float", "color", ...).
const char* param_type_name(ParamKind kind);

// The --json form of `dspbr params show`: {"parameters": {"<id>": {"name", "type", "default",
// "min", "max", "uniform", "hidden", "group", "uiOrder", ...}}} in UI order.
nlohmann::ordered_json material_def_to_json(const MaterialDef& m);

}  // namespace dspbr
