#include "dspbr/io/json_fields.h"

#include <cmath>
#include <stdexcept>

#include "dspbr/io/message.h"

namespace dspbr::json_fields {

namespace {

using Json = nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw std::runtime_error(path + " " + what); }

const char* kind(const Json& v) {
  switch (v.type()) {
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "a string";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::null: return "null";
    default: return "a number";
  }
}

}  // namespace

std::string member_path(const std::string& where, const std::string& key) { return where.empty() ? key : where + "." + key; }

std::string index_path(const std::string& where, std::size_t i) { return where + "[" + std::to_string(i) + "]"; }

std::string excerpt(const Json& v) {
  if (v.is_structured()) return std::string(kind(v)) + " of " + std::to_string(v.size());
  std::string s = v.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

template <class J>
std::string quoted(const J& v) {
  return quote_input(v.dump(-1, ' ', false, J::error_handler_t::replace));
}
template std::string quoted<nlohmann::json>(const nlohmann::json&);
template std::string quoted<nlohmann::ordered_json>(const nlohmann::ordered_json&);

const Json& member(const Json& obj, const std::string& key, const std::string& where) {
  if (!obj.is_object()) fail(where.empty() ? "the document" : where, "must be an object, got " + excerpt(obj));
  const auto it = obj.find(key);
  if (it == obj.end()) fail(member_path(where, key), "is missing");
  return *it;
}

const Json& object_member(const Json& obj, const std::string& key, const std::string& where) {
  const Json& v = member(obj, key, where);
  if (!v.is_object()) fail(member_path(where, key), "must be an object, got " + excerpt(v));
  return v;
}

const Json& array_member(const Json& obj, const std::string& key, const std::string& where) {
  const Json& v = member(obj, key, where);
  if (!v.is_array()) fail(member_path(where, key), "must be an array, got " + excerpt(v));
  return v;
}

std::string string_member(const Json& obj, const std::string& key, const std::string& where) {
  const Json& v = member(obj, key, where);
  if (!v.is_string()) fail(member_path(where, key), "must be a string, got " + excerpt(v));
  return v.get<std::string>();
}

double number_member(const Json& obj, const std::string& key, const std::string& where) {
  const Json& v = member(obj, key, where);
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    fail(member_path(where, key), "must be a finite number, got " + excerpt(v));
  return v.get<double>();
}

long long integer_member(const Json& obj, const std::string& key, const std::string& where, long long lo, long long hi) {
  const Json& v = member(obj, key, where);
  const bool in_range = v.is_number_unsigned()   ? v.get<unsigned long long>() <= static_cast<unsigned long long>(hi) &&
                                                       (lo <= 0 || v.get<unsigned long long>() >= static_cast<unsigned long long>(lo))
                        : v.is_number_integer() ? v.get<long long>() >= lo && v.get<long long>() <= hi
                                                 : false;
  if (!in_range)
    fail(member_path(where, key),
         "must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + excerpt(v));
  return v.get<long long>();
}

std::vector<double> numbers_member(const Json& obj, const std::string& key, const std::string& where, std::size_t count) {
  const Json& v = array_member(obj, key, where);
  const std::string path = member_path(where, key);
  if (v.size() != count)
    fail(path, "must hold " + std::to_string(count) + " numbers (the product of the axis sizes), got " +
                   std::to_string(v.size()));
  std::vector<double> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
      fail(index_path(path, i), "must be a finite number, got " + excerpt(v[i]));
    out.push_back(v[i].get<double>());
  }
  return out;
}

}  // namespace dspbr::json_fields
