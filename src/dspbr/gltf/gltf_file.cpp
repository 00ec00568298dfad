#include "dspbr/gltf/gltf_file.h"

#include "dspbr/limits.h"

#include "dspbr/gltf/gltf_uri.h"
#include "dspbr/io/json_fields.h"
#include "dspbr/io/message.h"
#include "dspbr/io/read_file.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
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

// An integer member of at least `min` (the glTF schema's "minimum"), `fallback` when absent and
// not required.
std::uint64_t count(const Json& obj, const char* key, const std::string& path, const std::string& where,
                    std::uint64_t fallback, bool required, std::uint64_t min = 0) {
  if (!obj.contains(key)) {
    if (required) fail(path, where + " has no \"" + key + "\"");
    return fallback;
  }
  const Json& v = obj[key];
  if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<long long>() >= 0))
    fail(path, where + ": \"" + key + "\" must be a non-negative integer, got " + json_fields::excerpt(v));
  const std::uint64_t n = v.get<std::uint64_t>();
  if (n < min) fail(path, where + ": \"" + key + "\" must be at least " + std::to_string(min) + ", got " + std::to_string(n));
  return n;
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
bool is_lfs_pointer(const RegularFile& file, std::uint64_t& announced) {
  if (file.size() > 1024) return false;  // pointers are ~130 bytes; the spec caps them at 1024
  std::istringstream in(file.read(1024));
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

// The file a local (non-data:) URI names, confined to the glTF's folder (gltf_uri.h).
std::string local_file(LocalUriResolver& uris, const std::string& path, const std::string& where,
                       const std::string& uri) {
  try {
    return uris.resolve(uri);
  } catch (const std::invalid_argument& e) {
    fail(path, where + ": " + e.what());
  }
}

std::uint64_t element_size(const Json& a, const std::string& path, const std::string& where);

void check_buffers(GltfFile& f, std::uint64_t bin_chunk_size, bool has_bin, LocalUriResolver& uris) {
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
  f.buffer_sizes.assign(buffers.size(), 0);
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    const Json& buf = buffers[i];
    const std::string where = "buffers[" + std::to_string(i) + "]";
    if (!buf.is_object()) fail(path, where + " must be an object");
    const std::uint64_t declared = count(buf, "byteLength", path, where, 0, true, 1);
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
        if (used[i]) fail(path, where + ": external URI '" + quote_input(uri) + "' is not a local file");
        continue;
      } else {
        const std::string file = local_file(uris, path, where, uri);
        std::unique_ptr<RegularFile> opened;
        try {
          opened = std::make_unique<RegularFile>(file);
        } catch (const std::runtime_error& e) {
          if (used[i]) fail(path, where + ": cannot read buffer file '" + quote_input(uri) + "': " + e.what());
          continue;
        }
        available = opened->size();
        std::uint64_t lfs_size = 0;
        if (is_lfs_pointer(*opened, lfs_size)) {
          if (used[i] && lfs_size < declared)
            fail(path, where + ": '" + quote_input(uri) + "' is a Git LFS pointer to " + std::to_string(lfs_size) +
                           " bytes, less than the declared byteLength " + std::to_string(declared));
          f.warnings.push_back(where + ": '" + quote_input(uri) + "' is a Git LFS pointer (" + std::to_string(lfs_size) +
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
    const std::uint64_t len = count(views[i], "byteLength", path, where, 0, true, 1);
    if (off > f.buffer_sizes[b] || len > f.buffer_sizes[b] - off)  // off + len may wrap around 2^64
      fail(path, where + " (bytes " + std::to_string(off) + ".." + std::to_string(off + len) + ") lies outside buffer " +
                     std::to_string(b) + " (" + std::to_string(f.buffer_sizes[b]) + " bytes)");
    view_sizes[i] = len;
  }
  std::vector<std::uint64_t> view_strides(views.size());
  for (std::size_t i = 0; i < views.size(); ++i) {
    const std::string where = "bufferViews[" + std::to_string(i) + "]";
    view_strides[i] = count(views[i], "byteStride", path, where, 0, false, 4);
    if (view_strides[i] > 252 || view_strides[i] % 4 != 0)
      fail(path, where + ": \"byteStride\" must be a multiple of 4 from 4 to 252, got " + std::to_string(view_strides[i]));
  }
  for (std::size_t i = 0; i < accessors.size(); ++i) {
    const std::string where = "accessors[" + std::to_string(i) + "]";
    const Json& a = accessors[i];
    if (!a.is_object()) fail(path, where + " must be an object");
    const std::uint64_t n = count(a, "count", path, where, 0, true, 1);
    const std::uint64_t element = element_size(a, path, where);
    if (!a.contains("bufferView")) continue;  // all zeros (or sparse): no storage
    const std::uint64_t v = count(a, "bufferView", path, where, 0, true);
    if (v >= views.size()) fail(path, where + " refers to bufferView " + std::to_string(v) + ", which does not exist");
    const std::uint64_t off = count(a, "byteOffset", path, where, 0, false);
    // The last element ends at off + stride * (count - 1) + element (glTF 2.0, 3.6.2.4), within
    // the view; compared without overflow.
    const std::uint64_t stride = view_strides[v] ? view_strides[v] : element, size = view_sizes[v];
    if (off > size || element > size - off || (n - 1) > (size - off - element) / stride)
      fail(path, where + ": " + std::to_string(n) + " elements of " + std::to_string(element) + " bytes from byteOffset " +
                     std::to_string(off) + " do not fit in bufferView " + std::to_string(v) + " (" + std::to_string(size) +
                     " bytes)");
  }
}

// Bytes of one accessor element (glTF 2.0, 3.6.2: componentType and type).
std::uint64_t element_size(const Json& a, const std::string& path, const std::string& where) {
  const std::uint64_t ct = count(a, "componentType", path, where, 0, true);
  const std::uint64_t component = ct == 5120 || ct == 5121 ? 1 : ct == 5122 || ct == 5123 ? 2 : ct == 5125 || ct == 5126 ? 4 : 0;
  if (component == 0) fail(path, where + ": \"componentType\" " + std::to_string(ct) + " is not a glTF component type");
  if (!a.contains("type") || !a["type"].is_string()) fail(path, where + ": \"type\" must be a string (SCALAR, VEC2, ...)");
  static const std::pair<const char*, int> kTypes[] = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                       {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
  for (const auto& [name, n] : kTypes)
    if (a["type"] == name) return component * std::uint64_t(n);
  fail(path, where + ": \"type\" " + json_fields::excerpt(a["type"]) + " is not a glTF accessor type");
}

// An index member (glTF "glTFid") that must name an element of the top-level array `target`.
void check_index(const Json& j, const Json& obj, const char* key, const char* target, const std::string& path,
                 const std::string& where) {
  if (!obj.is_object() || !obj.contains(key)) return;
  const std::uint64_t n = j.contains(target) && j[target].is_array() ? j[target].size() : 0;
  const std::uint64_t i = count(obj, key, path, where, 0, true);
  if (i >= n) fail(path, where + ": \"" + key + "\" refers to " + target + "[" + std::to_string(i) + "], which does not exist");
}

// Each element of the array member `key` of `obj` (when present), which must be an array.
template <class F>
void each(const Json& obj, const char* key, const std::string& path, const std::string& where, F f) {
  if (!obj.is_object() || !obj.contains(key)) return;
  const Json& arr = obj[key];
  if (!arr.is_array()) fail(path, where + ": \"" + key + "\" must be an array");
  for (std::size_t i = 0; i < arr.size(); ++i) f(arr[i], where + (where.empty() ? "" : ".") + key + "[" + std::to_string(i) + "]");
}

// The references between top-level arrays (glTF 2.0 schema: indices within their arrays) and
// the "extensions" members, which are objects of objects wherever they appear.
void check_references(const Json& j, const std::string& path, LocalUriResolver& uris) {
  each(j, "meshes", path, "", [&](const Json& mesh, const std::string& w) {
    each(mesh, "primitives", path, w, [&](const Json& prim, const std::string& wp) {
      if (!prim.is_object()) fail(path, wp + " must be an object");
      check_index(j, prim, "indices", "accessors", path, wp);
      check_index(j, prim, "material", "materials", path, wp);
      if (prim.contains("attributes")) {
        if (!prim["attributes"].is_object()) fail(path, wp + ": \"attributes\" must be an object");
        for (const auto& [name, v] : prim["attributes"].items())
          check_index(j, prim["attributes"], name.c_str(), "accessors", path, wp + ".attributes");
      }
    });
  });
  each(j, "nodes", path, "", [&](const Json& node, const std::string& w) {
    check_index(j, node, "mesh", "meshes", path, w);
    check_index(j, node, "camera", "cameras", path, w);
    check_index(j, node, "skin", "skins", path, w);
    each(node, "children", path, w, [&](const Json& c, const std::string& wc) {
      check_index(j, Json{{"node", c}}, "node", "nodes", path, wc);
    });
  });
  each(j, "scenes", path, "", [&](const Json& scene, const std::string& w) {
    each(scene, "nodes", path, w, [&](const Json& n, const std::string& wn) {
      check_index(j, Json{{"node", n}}, "node", "nodes", path, wn);
    });
  });
  check_index(j, j, "scene", "scenes", path, "the asset");
  each(j, "textures", path, "", [&](const Json& t, const std::string& w) {
    check_index(j, t, "source", "images", path, w);
    check_index(j, t, "sampler", "samplers", path, w);
  });
  each(j, "images", path, "", [&](const Json& im, const std::string& w) {
    if (!im.is_object()) fail(path, w + " must be an object");
    check_index(j, im, "bufferView", "bufferViews", path, w);
    if (im.contains("uri")) {
      if (!im["uri"].is_string()) fail(path, w + ": \"uri\" must be a string");
      const std::string uri = im["uri"].get<std::string>();
      if (uri.rfind("data:", 0) != 0 && uri.find("://") == std::string::npos) local_file(uris, path, w, uri);
    }
  });
  // "extensions" (glTF 2.0, 3.12): an object whose members are objects, anywhere in the asset.
  // Depth first with one frame per level (limits::kJsonDepth): a member's path is spelled only
  // for a message, so millions of elements cost no memory beyond the parsed JSON.
  struct Frame {
    const Json* v;
    Json::const_iterator it;  // the member being visited
    std::size_t index;        // its position, for arrays
  };
  std::vector<Frame> stack;
  auto where = [&](const std::string& last) {
    std::string w;
    for (const Frame& f : stack)
      w += f.v->is_object() ? (w.empty() ? "" : ".") + f.it.key() : "[" + std::to_string(f.index) + "]";
    return w + last;
  };
  if (j.is_structured()) stack.push_back({&j, j.cbegin(), 0});
  while (!stack.empty()) {
    Frame& f = stack.back();
    if (f.it == f.v->cend()) {
      stack.pop_back();
      if (!stack.empty()) ++stack.back().it, ++stack.back().index;
      continue;
    }
    const Json& member = *f.it;
    if (f.v->is_object() && f.it.key() == "extras") {
      ++f.it, ++f.index;
      continue;
    }
    if (f.v->is_object() && f.it.key() == "extensions") {
      if (!member.is_object()) fail(path, quote_input(where("")) + " must be an object, got " + json_fields::excerpt(member));
      for (const auto& [name, ext] : member.items())
        if (!ext.is_object()) fail(path, quote_input(where("." + name)) + " must be an object, got " + json_fields::excerpt(ext));
    }
    if (member.is_structured() && !member.empty())
      stack.push_back({&member, member.cbegin(), 0});
    else
      ++f.it, ++f.index;
  }
}

}  // namespace

namespace {

// The checks on a parsed document (the GLB's BIN chunk: `has_bin`, `bin_size` bytes).
void check_gltf(GltfFile& f, std::uint64_t bin_size, bool has_bin) {
  const std::string& path = f.path;
  if (!f.json.is_object()) fail(path, "the glTF JSON must be an object");
  if (!f.json.contains("asset") || !f.json["asset"].is_object() || !f.json["asset"].contains("version"))
    fail(path, "not a glTF asset: missing \"asset\": {\"version\": \"2.0\"}");
  const Json& version = f.json["asset"]["version"];
  if (!version.is_string() || version.get<std::string>().rfind("2.", 0) != 0)
    fail(path, "glTF asset version " + json_fields::quoted(version) + " is not supported (expected \"2.x\")");
  LocalUriResolver uris(path);
  check_buffers(f, bin_size, has_bin, uris);
  check_references(f.json, path, uris);
}

std::uint32_t le32(const char* p) { return le32(reinterpret_cast<const std::uint8_t*>(p)); }

}  // namespace

GltfFile gltf_from_json(Json json, const std::string& path) {
  GltfFile f;
  f.path = path;
  f.json = std::move(json);
  check_gltf(f, 0, false);
  return f;
}

GltfFile parse_gltf(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  return parse_gltf(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
}

GltfFile parse_gltf(std::string_view bytes, const std::string& path) {
  GltfFile f;
  f.path = path;
  std::uint64_t bin_size = 0;
  bool has_bin = false;
  const char* json_begin = bytes.data();
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
  check_gltf(f, bin_size, has_bin);
  return f;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

GltfFile read_gltf(const std::string& path) {
  return parse_gltf(std::string_view(read_file(path, limits::kGltfBytes)), path);
}

}  // namespace dspbr::gltf
