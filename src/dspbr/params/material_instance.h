// Material instance files: {"material": "<type>", "values": {"<id>": value, ...}} (docs/params.md),
// validated against the resolved parameter definitions of a parameter file
// (params-2025x.json format, see param_defs.h) and converted into the reference BSDF's Material.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dspbr/material.h"

namespace dspbr {

class ParamDefs;

// The definitions used when no file is given: the file $DSPBR_PARAMS names if set (read at each
// call; errors as ParamDefs::load, after "$DSPBR_PARAMS: "), else ParamDefs::builtin().
ParamDefs default_param_defs();

// Every problem of an instance document against the definitions, one clear message each
// (unknown material type, unknown parameter, wrong type, out of range, wrong vector length,
// hidden parameter set). Empty when the instance is valid.
std::vector<std::string> check_material_instance(const ParamDefs& defs, const nlohmann::json& instance);

// Converts a valid instance: starts from the material type's resolved defaults and applies the
// values with set_material_parameter. Throws std::runtime_error listing the problems when the
// instance is not valid.
Material material_from_instance(const ParamDefs& defs, const nlohmann::json& instance);

// Reads, validates and converts the instance file at `path` against default_param_defs().
// Throws std::runtime_error with a one-line message naming the file and the problem(s) (unreadable
// file, malformed JSON, invalid instance). Used by `dspbr eval --material FILE`.
Material load_material_instance(const std::string& path);

}  // namespace dspbr
