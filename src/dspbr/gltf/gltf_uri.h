// Where a glTF's URI may lead (docs/limits.md, "Confinement"): a buffer or image URI that is not
// a data: URI names a file inside the glTF's own folder. The URI is percent-decoded (RFC 3986,
// 2.1), must be a relative path, and is resolved component by component with lstat: ".." may not
// leave the folder and a symbolic link is followed only while its target stays inside. Nothing
// outside the folder is touched (not even stat), so no message can tell anything about it.
#pragma once
#include <string>
#include <utility>

namespace dspbr::gltf {

// RFC 3986 percent-decoding; throws std::invalid_argument on a malformed escape or a NUL byte,
// raw (a JSON string may hold \u0000) or encoded.
std::string percent_decode(const std::string& uri);

// Resolves the local URIs of one glTF: its folder is found once (a glTF may hold millions of
// image URIs; each then costs one lstat per path component).
class LocalUriResolver {
 public:
  explicit LocalUriResolver(std::string gltf_path) : gltf_path_(std::move(gltf_path)) {}
  // The file `uri` names, inside the glTF's folder. Throws std::invalid_argument
  // "URI '<uri>' <reason>" (absolute, leaves the glTF's folder, leaves it through a symbolic
  // link, too many links, malformed escape, the folder cannot be read).
  std::string resolve(const std::string& uri);

 private:
  std::string gltf_path_;
  std::string base_;  // the folder's canonical path, once a URI needed it
};

// One URI: LocalUriResolver(gltf_path).resolve(uri).
std::string resolve_local_uri(const std::string& gltf_path, const std::string& uri);

}  // namespace dspbr::gltf
