#include "dspbr/io/read_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "dspbr/limits.h"

namespace dspbr {

namespace fs = std::filesystem;

std::string read_file(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) throw std::runtime_error(path + " does not exist");
  if (st.type() == fs::file_type::directory) throw std::runtime_error(path + " is a directory");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw std::runtime_error(path + " cannot be read: " + std::strerror(errno));
  std::string out;
  char buf[65536];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) out.append(buf, n);
  const bool failed = std::ferror(f);
  const int err = errno;
  std::fclose(f);
  if (failed) throw std::runtime_error(path + " cannot be read: " + std::strerror(err));
  return out;
}

std::string sniff_format(std::string_view bytes) {
  struct Magic {
    std::string_view start;
    const char* name;
  };
  // Signatures from each format's specification (first bytes of the file).
  static const Magic kMagics[] = {
      {std::string_view("\x89PNG\r\n\x1a\n", 8), "a PNG image"},
      {std::string_view("\xff\xd8\xff", 3), "a JPEG image"},
      {"glTF", "a binary glTF (GLB)"},
      {std::string_view("\x76\x2f\x31\x01", 4), "an OpenEXR image"},
      {std::string_view("PK\x03\x04", 4), "a ZIP archive"},
      {std::string_view("\x1f\x8b", 2), "a gzip file"},
      {"%PDF-", "a PDF document"},
  };
  for (const auto& m : kMagics)
    if (bytes.substr(0, m.start.size()) == m.start) return m.name;
  return "";
}

namespace {

std::string printable(std::string_view s) {
  std::string out;
  for (unsigned char c : s) {
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  return out;
}

// Throws when arrays and objects nest deeper than limits::kJsonDepth (before parsing: the parser
// itself is iterative, but copies, merges and dumps of the document recurse per level). Brackets
// inside strings do not count.
void check_nesting(std::string_view text, const std::string& path) {
  int depth = 0;
  long line = 1;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (c == '\n') ++line;
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limits::kJsonDepth)
        throw std::runtime_error(path + ": JSON nested deeper than " + std::to_string(limits::kJsonDepth) +
                                 " levels (line " + std::to_string(line) + ")");
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

}  // namespace

template <class Json>
Json parse_json(std::string_view text, const std::string& path, const std::string& what) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) throw std::runtime_error(path + " is empty");
  if (const std::string format = sniff_format(text); !format.empty())
    throw std::runtime_error(path + " is not a " + what + " (it starts like " + format + ")");
  check_nesting(text, path);
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line L, column C: ...".
    std::string detail = e.what();
    const std::string marker = "parse error at ";
    if (const auto pos = detail.find(marker); pos != std::string::npos) detail = "at " + detail.substr(pos + marker.size());
    throw std::runtime_error(path + ": malformed JSON " + printable(detail));
  }
}

template nlohmann::json parse_json<nlohmann::json>(std::string_view, const std::string&, const std::string&);
template nlohmann::ordered_json parse_json<nlohmann::ordered_json>(std::string_view, const std::string&,
                                                                   const std::string&);

}  // namespace dspbr
