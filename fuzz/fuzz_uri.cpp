// libFuzzer target: glTF URI resolution (gltf/gltf_uri.h) against a folder tree with links that
// stay inside, links that leave (relative and absolute) and a loop. The input is the URI. Checked
// property, beyond "no crash": a resolved path lies inside the glTF's folder after every link is
// followed (realpath of its existing part); anything else aborts the run.
#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "dspbr/gltf/gltf_uri.h"
#include "temp_folder.h"

namespace fs = std::filesystem;

namespace {

// root/scene/{sub/a.bin, in -> sub, in_abs -> <root>/scene/sub, out -> .., out_abs -> <root>,
// loop -> loop}, root/secret.bin.
const fs::path& scene() {
  static const TempFolder scratch("dspbr-fuzz-uri");
  static const fs::path dir = [] {
    const fs::path root = scratch.path(), s = root / "scene";
    fs::create_directories(s / "sub" / "deeper");
    std::ofstream(s / "sub" / "a.bin") << "a";
    std::ofstream(root / "secret.bin") << "s";
    fs::create_directory_symlink("sub", s / "in");
    fs::create_directory_symlink(s / "sub", s / "in_abs");
    fs::create_directory_symlink("..", s / "out");
    fs::create_directory_symlink(root, s / "out_abs");
    fs::create_directory_symlink("../..", s / "sub" / "up2");
    fs::create_symlink("loop", s / "loop");
    return s;
  }();
  return dir;
}

// The deepest existing ancestor of `p`, with every link resolved, then the rest appended.
fs::path resolved(const fs::path& p) {
  fs::path existing = p, rest;
  std::error_code ec;
  while (!fs::exists(fs::symlink_status(existing, ec)) && existing.has_parent_path() && existing != existing.parent_path()) {
    rest = existing.filename() / rest;
    existing = existing.parent_path();
  }
  const fs::path c = fs::weakly_canonical(existing, ec);
  return ec ? p : (c / rest).lexically_normal();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string uri(reinterpret_cast<const char*>(data), size);
  const fs::path base = scene();
  std::string file;
  try {
    file = dspbr::gltf::resolve_local_uri((base / "x.gltf").string(), uri);
  } catch (const std::invalid_argument&) {
    return 0;
  }
  const std::string r = resolved(file).string(), b = base.string() + "/";
  if (r != base.string() && r.rfind(b, 0) != 0) {
    std::fprintf(stderr, "URI resolved outside the folder: '%s' -> '%s' (%s)\n", uri.c_str(), file.c_str(), r.c_str());
    std::abort();
  }
  return 0;
}
