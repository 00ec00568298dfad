// Reading input files with one-line error messages that name the file and the problem
// (std::runtime_error): missing, a directory, unreadable, empty, or not JSON — saying what the
// file starts like when it is a well-known binary format. Used by the readers of user-given files
// (parameter definitions, material instances, glTF scenes).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace dspbr {

// The whole file. Throws "<path> does not exist", "<path> is a directory" or
// "<path> cannot be read: <reason>".
std::string read_file(const std::string& path);

// What `bytes` start like when they are a well-known non-JSON format ("a PNG image",
// "a JPEG image", "a binary glTF (GLB)", "an OpenEXR image", "a ZIP archive", "a gzip file",
// "a PDF document"), else "".
std::string sniff_format(std::string_view bytes);

// Parses `text`, the JSON content of `path` (a `what`, e.g. "glTF file"). Throws "<path> is empty"
// for blank text, "<path> is not a <what> (it starts like a PNG image)" when sniff_format
// recognizes the bytes, "<path>: JSON nested deeper than N levels (line L)" past
// limits::kJsonDepth, and on malformed JSON "<path>: malformed JSON at line L, column C: <reason>";
// bytes outside printable ASCII in the parser's excerpt are written \xNN, so the message stays
// one line.
template <class Json = nlohmann::json>
Json parse_json(std::string_view text, const std::string& path, const std::string& what);

// read_file + parse_json.
template <class Json = nlohmann::json>
Json read_json_file(const std::string& path, const std::string& what) {
  return parse_json<Json>(read_file(path), path, what);
}

extern template nlohmann::json parse_json<nlohmann::json>(std::string_view, const std::string&, const std::string&);
extern template nlohmann::ordered_json parse_json<nlohmann::ordered_json>(std::string_view, const std::string&,
                                                                          const std::string&);

}  // namespace dspbr
