// Reading a glTF 2.0 asset: .gltf (JSON) or .glb (binary container: 12-byte header, JSON chunk,
// optional BIN chunk; glTF 2.0 spec section "GLB File Format Specification"). Only what material
// analysis needs is kept: the JSON document and the size of every buffer. Geometry and images are
// not decoded; buffers that bufferViews use must exist and be large enough.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace dspbr::gltf {

struct GltfFile {
  std::string path;
  nlohmann::json json;                    // the glTF JSON document
  std::vector<std::uint64_t> buffer_sizes;  // bytes available for each entry of "buffers"
  bool binary = false;                    // read from .glb
  // Non-fatal findings, e.g. a buffer file that is a Git LFS pointer (content not fetched):
  // materials are unaffected, geometry is unavailable.
  std::vector<std::string> warnings;
};

// Reads and checks a .gltf or .glb file (chosen by the file's magic, not its name). Throws
// std::runtime_error naming the file and the problem for a missing, unreadable or non-JSON file
// (read_file.h), malformed JSON, a bad GLB header
// or chunk (magic, version, lengths), a missing or short buffer referenced by a bufferView, or a
// bufferView / accessor outside its buffer. A buffer file that is a Git LFS pointer announcing at
// least byteLength bytes is accepted with a warning (materials do not need the geometry).
GltfFile read_gltf(const std::string& path);

// Same from bytes in memory; `path` names the asset in messages and locates external buffers.
GltfFile parse_gltf(std::string_view bytes, const std::string& path);
GltfFile parse_gltf(const std::vector<std::uint8_t>& bytes, const std::string& path);

// Same from the JSON of a .gltf file already parsed (read_file.h's parse_json), which is moved
// in: a caller that looked at the document first does not hold two copies.
GltfFile gltf_from_json(nlohmann::json json, const std::string& path);

// The extension of a file name in lower case (".GLTF" -> ".gltf"): scene folders list .gltf and
// .glb files in any case (a file from a case-insensitive file system was skipped without a word;
// the sixth fresh tester's pass).
std::string lower_extension(const std::string& path);

}  // namespace dspbr::gltf
