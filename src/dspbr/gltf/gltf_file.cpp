#include "dspbr/gltf/gltf_file.h"

#include "dspbr/io/read_file.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace dspbr::gltf {

namespace {

using Json = nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw std::runtime_error(path + ": " + what); }

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

std::uint32_t le32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

std::uint64_t count(const Json& obj, const char* key, const std::string& path, const std::string& where,
                    std::uint64_t fallback, bool required) {
  if (!obj.contains(key)) {
    if (required) fail(path, where + " has no \"" + key + "\"");
    return fallback;
  }
  const Json& v = obj[key];
  if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<long long>() >= 0))
    fail(path, where + ": \"" + key + "\" must be a non-negative integer, got " + v.dump());
  return v.get<std::uint64_t>();
}

// Decoded size of a base64 "data:" URI payload (RFC 4648); throws on characters outside the alphabet.
std::uint64_t base64_size(const std::string& data, const std::string& path, const std::string& where) {
  std::uint64_t n = 0, pad = 0;
  for (char c : data) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/') {
      if (pad) fail(path, where + ": malformed base64 data URI");
      ++n;
    } else if (c == '=') {
      ++pad;
    } else {
      fail(path, where + ": malformed base64 data URI");
    }
  }
  return n * 6 / 8;
}

// A Git LFS pointer file (https://github.com/git-lfs/git-lfs/blob/main/docs/spec.md): small text
// starting with "version https://git-lfs.github.com/spec/v1" and holding "size <bytes>".
bool is_lfs_pointer(const std::string& file, std::uint64_t file_size, std::uint64_t& announced) {
  if (file_size > 1024) return false;  // pointers are ~130 bytes; the spec caps them at 1024
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line) || line.rfind("version https://git-lfs.github.com/spec/", 0) != 0) return false;
  while (std::getline(in, line))
    if (line.rfind("size ", 0) == 0) {
      // Digits only (std::stoull would take "-5" as 2^64 - 5), below 2^64.
      const std::string digits = line.substr(5);
      if (digits.empty() || digits.size() > 19 || digits.find_first_not_of("0123456789") != std::string::npos)
        return false;
      announced = std::stoull(digits);
      return true;
    }
  return false;
}

std::string percent_decode(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

void check_buffers(GltfFile& f, std::uint64_t bin_chunk_size, bool has_bin) {
  const std::string& path = f.path;
  const Json& j = f.json;
  auto array = [&](const char* key) -> const Json& {
    static const Json empty = Json::array();
    if (!j.contains(key)) return empty;
    if (!j[key].is_array()) fail(path, std::string("\"") + key + "\" must be an array");
    return j[key];
  };
  const Json& buffers = array("buffers");
  const Json& views = array("bufferViews");
  const Json& accessors = array("accessors");
  // Which buffers are used: a missing buffer matters only when a bufferView points into it.
  std::vector<bool> used(buffers.size(), false);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const std::string where = "bufferViews[" + std::to_string(i) + "]";
    if (!views[i].is_object()) fail(path, where + " must be an object");
    const std::uint64_t b = count(views[i], "buffer", path, where, 0, true);
    if (b >= buffers.size()) fail(path, where + " refers to buffer " + std::to_string(b) + ", which does not exist");
    used[b] = true;
  }
  const std::string dir = std::filesystem::path(path).parent_path().string();
  f.buffer_sizes.assign(buffers.size(), 0);
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    const Json& buf = buffers[i];
    const std::string where = "buffers[" + std::to_string(i) + "]";
    if (!buf.is_object()) fail(path, where + " must be an object");
    const std::uint64_t declared = count(buf, "byteLength", path, where, 0, true);
    std::uint64_t available = 0;
    if (!buf.contains("uri")) {
      // GLB: the first buffer without uri is the BIN chunk (glTF 2.0, "Binary buffer").
      if (!(f.binary && i == 0)) fail(path, where + " has no \"uri\" (only the first buffer of a .glb may omit it)");
      if (!has_bin) {
        if (used[i]) fail(path, where + " refers to the GLB's BIN chunk, which is missing");
        continue;
      }
      available = bin_chunk_size;
    } else {
      if (!buf["uri"].is_string()) fail(path, where + ": \"uri\" must be a string");
      const std::string uri = buf["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) {
        const auto comma = uri.find(',');
        if (comma == std::string::npos || uri.substr(0, comma).find(";base64") == std::string::npos)
          fail(path, where + ": only base64 data URIs are supported");
        available = base64_size(uri.substr(comma + 1), path, where);
      } else if (uri.find("://") != std::string::npos) {
        if (used[i]) fail(path, where + ": external URI '" + uri + "' is not a local file");
        continue;
      } else {
        const std::string file = (std::filesystem::path(dir) / percent_decode(uri)).string();
        std::error_code ec;
        const auto size = std::filesystem::file_size(file, ec);
        if (ec || !std::ifstream(file, std::ios::binary)) {
          if (used[i]) fail(path, where + ": cannot read buffer file '" + file + "'");
          continue;
        }
        available = size;
        std::uint64_t lfs_size = 0;
        if (is_lfs_pointer(file, size, lfs_size)) {
          if (used[i] && lfs_size < declared)
            fail(path, where + ": '" + uri + "' is a Git LFS pointer to " + std::to_string(lfs_size) +
                           " bytes, less than the declared byteLength " + std::to_string(declared));
          f.warnings.push_back(where + ": '" + uri + "' is a Git LFS pointer (" + std::to_string(lfs_size) +
                               " bytes not fetched): geometry unavailable, materials unaffected");
          available = lfs_size;
        }
      }
    }
    if (used[i] && available < declared)
      fail(path, where + " declares " + std::to_string(declared) + " bytes but only " + std::to_string(available) +
                     " are available");
    f.buffer_sizes[i] = std::min(available, declared);
  }
  std::vector<std::uint64_t> view_sizes(views.size());
  for (std::size_t i = 0; i < views.size(); ++i) {
    const std::string where = "bufferViews[" + std::to_string(i) + "]";
    const std::uint64_t b = count(views[i], "buffer", path, where, 0, true);
    const std::uint64_t off = count(views[i], "byteOffset", path, where, 0, false);
    const std::uint64_t len = count(views[i], "byteLength", path, where, 0, true);
    if (off > f.buffer_sizes[b] || len > f.buffer_sizes[b] - off)  // off + len may wrap around 2^64
      fail(path, where + " (bytes " + std::to_string(off) + ".." + std::to_string(off + len) + ") lies outside buffer " +
                     std::to_string(b) + " (" + std::to_string(f.buffer_sizes[b]) + " bytes)");
    view_sizes[i] = len;
  }
  for (std::size_t i = 0; i < accessors.size(); ++i) {
    const std::string where = "accessors[" + std::to_string(i) + "]";
    if (!accessors[i].is_object()) fail(path, where + " must be an object");
    if (!accessors[i].contains("bufferView")) continue;  // all zeros (or sparse): no storage
    const std::uint64_t v = count(accessors[i], "bufferView", path, where, 0, true);
    if (v >= views.size()) fail(path, where + " refers to bufferView " + std::to_string(v) + ", which does not exist");
    const std::uint64_t off = count(accessors[i], "byteOffset", path, where, 0, false);
    if (off > view_sizes[v]) fail(path, where + ": byteOffset lies outside bufferView " + std::to_string(v));
  }
}

}  // namespace

GltfFile parse_gltf(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  GltfFile f;
  f.path = path;
  std::uint64_t bin_size = 0;
  bool has_bin = false;
  const char* json_begin = reinterpret_cast<const char*>(bytes.data());
  std::size_t json_size = bytes.size();
  if (bytes.size() >= 4 && le32(bytes.data()) == kGlbMagic) {
    f.binary = true;
    if (bytes.size() < 12) fail(path, "truncated GLB: the 12-byte header is incomplete");
    const std::uint32_t version = le32(bytes.data() + 4), length = le32(bytes.data() + 8);
    if (version != 2) fail(path, "GLB version " + std::to_string(version) + " is not supported (expected 2)");
    if (length != bytes.size())
      fail(path, "truncated or padded GLB: header says " + std::to_string(length) + " bytes, the file has " +
                     std::to_string(bytes.size()));
    std::size_t pos = 12;
    int chunk = 0;
    while (pos < bytes.size()) {
      if (bytes.size() - pos < 8) fail(path, "truncated GLB: chunk " + std::to_string(chunk) + " header is incomplete");
      const std::uint32_t clen = le32(bytes.data() + pos), ctype = le32(bytes.data() + pos + 4);
      pos += 8;
      if (clen > bytes.size() - pos)
        fail(path, "truncated GLB: chunk " + std::to_string(chunk) + " declares " + std::to_string(clen) + " bytes, only " +
                       std::to_string(bytes.size() - pos) + " remain");
      if (chunk == 0) {
        if (ctype != kChunkJson) fail(path, "malformed GLB: the first chunk is not of type JSON");
        json_begin = reinterpret_cast<const char*>(bytes.data() + pos);
        json_size = clen;
      } else if (chunk == 1 && ctype == kChunkBin) {
        has_bin = true;
        bin_size = clen;
      }  // other chunk types: ignored, as the GLB specification asks
      pos += clen;
      ++chunk;
    }
    if (chunk == 0) fail(path, "malformed GLB: no JSON chunk");
  }
  f.json = parse_json(std::string_view(json_begin, json_size), path, "glTF file");
  if (!f.json.is_object()) fail(path, "the glTF JSON must be an object");
  if (!f.json.contains("asset") || !f.json["asset"].is_object() || !f.json["asset"].contains("version"))
    fail(path, "not a glTF asset: missing \"asset\": {\"version\": \"2.0\"}");
  const Json& version = f.json["asset"]["version"];
  if (!version.is_string() || version.get<std::string>().rfind("2.", 0) != 0)
    fail(path, "glTF asset version " + version.dump() + " is not supported (expected \"2.x\")");
  check_buffers(f, bin_size, has_bin);
  return f;
}

GltfFile read_gltf(const std::string& path) {
  const std::string bytes = read_file(path);
  return parse_gltf({bytes.begin(), bytes.end()}, path);
}

}  // namespace dspbr::gltf
