// JSON output that never holds a non-finite number: the JSON library writes NaN and infinity as
// null, which a reader takes for a missing value. Every JSON the project writes (files and stdout)
// goes through json_text, which refuses such a value naming its JSON path.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace dspbr {

// The JSON path of the first NaN or infinite number in `j` ("materials[0].emission[1]", below
// `path`), or nullopt when every number is finite.
template <class Json>
std::optional<std::string> non_finite_path(const Json& j, const std::string& path = "");

// j.dump(indent); throws std::runtime_error "<what>: the value at <path> is not finite (NaN or
// infinity); nothing written" when j holds one.
template <class Json>
std::string json_text(const Json& j, int indent, const std::string& what);

extern template std::optional<std::string> non_finite_path<nlohmann::json>(const nlohmann::json&, const std::string&);
extern template std::optional<std::string> non_finite_path<nlohmann::ordered_json>(const nlohmann::ordered_json&,
                                                                                   const std::string&);
extern template std::string json_text<nlohmann::json>(const nlohmann::json&, int, const std::string&);
extern template std::string json_text<nlohmann::ordered_json>(const nlohmann::ordered_json&, int, const std::string&);

}  // namespace dspbr
