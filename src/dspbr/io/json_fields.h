// Typed members of a JSON input document, with one-line messages that name the JSON path of the
// offending value and what it holds instead, e.g. "tables.GGX_E.axes[0].name must be a string,
// got 5" (std::runtime_error; the caller prefixes the file). Used by the table file readers.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace dspbr::json_fields {

// "where.key" ("key" when where is empty) and "where[i]".
std::string member_path(const std::string& where, const std::string& key);
std::string index_path(const std::string& where, std::size_t i);

// A short excerpt of a value for messages (at most ~60 characters).
std::string excerpt(const nlohmann::json& v);

// A value quoted in a message as its JSON text, cut like other quoted input (io/message.h:
// kQuoteChars characters, then "..."; invalid UTF-8 replaced, never an exception).
template <class Json>
std::string quoted(const Json& v);

// obj[key]; throws "<where> must be an object" or "<where>.<key> is missing".
const nlohmann::json& member(const nlohmann::json& obj, const std::string& key, const std::string& where);
const nlohmann::json& object_member(const nlohmann::json& obj, const std::string& key, const std::string& where);
const nlohmann::json& array_member(const nlohmann::json& obj, const std::string& key, const std::string& where);
std::string string_member(const nlohmann::json& obj, const std::string& key, const std::string& where);
// A finite number.
double number_member(const nlohmann::json& obj, const std::string& key, const std::string& where);
// An integer in [lo, hi].
long long integer_member(const nlohmann::json& obj, const std::string& key, const std::string& where, long long lo,
                         long long hi);
// An array of exactly `count` finite numbers (the count is checked before anything is converted).
std::vector<double> numbers_member(const nlohmann::json& obj, const std::string& key, const std::string& where,
                                   std::size_t count);

}  // namespace dspbr::json_fields
