// The conformance vector document (docs/conformance.md, "Schema"): written as JSON
// {"format": "dspbr-conformance", "version": 1, "provenance": {...}, "vectors": [...]} and as a CSV of
// the same records; read back (JSON) by the checker with one-line messages naming the file and
// the record.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dspbr/conformance/vector.h"

namespace dspbr::conformance {

nlohmann::ordered_json vector_json(const Vector& v);
nlohmann::ordered_json vectors_document(const std::vector<Vector>& vectors, const nlohmann::ordered_json& provenance);

// One line per vector: id,group,components (';'-separated),material (instance JSON, CSV-quoted),
// options (JSON, CSV-quoted; empty for the defaults),v_x,v_y,v_z,l_x,l_y,l_z,f_cos_r,f_cos_g,f_cos_b,tol_abs,tol_rel,pdf,pdf_tol_abs,pdf_tol_rel,
// albedo_r,albedo_g,albedo_b,albedo_tol_abs,albedo_tol_rel (empty without an albedo). Numbers
// written to round trip (%.17g). Delta lobes, emission and glTF materials are in the JSON only.
std::string vectors_csv(const std::vector<Vector>& vectors);

// obj[key] as 3 finite numbers; throws "<where>.<key> must be an array of 3 numbers, got ..." or
// the json_fields message naming the element that is not a finite number.
Rgb read_rgb(const nlohmann::json& obj, const std::string& key, const std::string& where);

// Reads a vector document (a file written by `dspbr conformance generate`); the ids are unique.
// Throws std::runtime_error "<path>: vectors[i] (id 'x'): <problem>" (or "<path>: <problem>").
std::vector<Vector> read_vectors(const std::string& path);
// Same from a parsed document; `path` names it in messages.
std::vector<Vector> vectors_from_json(const nlohmann::json& doc, const std::string& path);

}  // namespace dspbr::conformance
