// Access to Material fields by their JSON id (params-2025x.json), shared by the CLI (--set),
// material instance files and glTF import. Types follow the spec's "Parameter JSON file format":
// float, color (3 numbers), normal / vector (3 numbers), boolean, enum (string).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dspbr/material.h"

namespace dspbr {

enum class ParamKind { Float, Color, Normal, Vector, Boolean, Enum };

// The 38 ids of the generic material, in params-2025x.json's uiOrder.
const std::vector<std::string>& material_parameter_ids();
// Kind of a parameter; throws std::invalid_argument for an unknown id.
ParamKind material_parameter_kind(const std::string& id);

// Sets one parameter from a JSON value (numbers for float, arrays of 3 numbers for colour /
// normal / vector, true/false for boolean, the enum's string; {"infinity": true} for +inf).
// Throws std::invalid_argument naming the parameter and the expected type. No range checks here:
// ranges are the BSDF's business (validate_material).
void set_material_parameter(Material& m, const std::string& id, const nlohmann::json& value);
// Reads one parameter as JSON (+inf as {"infinity": true}).
nlohmann::json get_material_parameter(const Material& m, const std::string& id);

// Parses a command-line value ("0.3", "1,0.5,0.2", "true", "LUMINOUS_POWER", "inf") into the
// JSON value set_material_parameter expects for that parameter's kind.
nlohmann::json parse_parameter_text(const std::string& id, const std::string& text);

}  // namespace dspbr
