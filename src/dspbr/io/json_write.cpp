#include "dspbr/io/json_write.h"

#include <cmath>
#include <stdexcept>

#include "dspbr/io/json_fields.h"

namespace dspbr {

template <class Json>
std::optional<std::string> non_finite_path(const Json& j, const std::string& path) {
  if (j.is_number_float()) return std::isfinite(j.template get<double>()) ? std::nullopt : std::optional(path);
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      if (auto p = non_finite_path(it.value(), json_fields::member_path(path, it.key()))) return p;
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      if (auto p = non_finite_path(j[i], json_fields::index_path(path, i))) return p;
  }
  return std::nullopt;
}

template <class Json>
std::string json_text(const Json& j, int indent, const std::string& what) {
  if (const auto p = non_finite_path(j))
    throw std::runtime_error(what + ": the value at " + (p->empty() ? "the top" : *p) +
                             " is not finite (NaN or infinity); nothing written");
  return j.dump(indent);
}

template std::optional<std::string> non_finite_path<nlohmann::json>(const nlohmann::json&, const std::string&);
template std::optional<std::string> non_finite_path<nlohmann::ordered_json>(const nlohmann::ordered_json&,
                                                                            const std::string&);
template std::string json_text<nlohmann::json>(const nlohmann::json&, int, const std::string&);
template std::string json_text<nlohmann::ordered_json>(const nlohmann::ordered_json&, int, const std::string&);

}  // namespace dspbr
