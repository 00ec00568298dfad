// libFuzzer target: glTF and GLB assets (gltf/gltf_file.h) and their materials mapped to DSPBR
// parameters (gltf/gltf_material.h), as `dspbr scene analyze` reads them. The asset lies in an
// empty folder of its own (URIs resolve there, gltf/gltf_uri.h: external buffers do not exist).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include "dspbr/gltf/gltf_file.h"
#include "dspbr/gltf/gltf_material.h"
#include "temp_folder.h"

namespace {

const std::string& asset_path() {
  static const TempFolder dir("dspbr-fuzz-gltf");
  static const std::string path = (dir.path() / "fuzz.gltf").string();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const dspbr::gltf::GltfFile f = dspbr::gltf::parse_gltf(std::vector<std::uint8_t>(data, data + size),
                                                            asset_path());
    (void)dspbr::gltf::map_materials(f);
  } catch (const std::exception&) {
  }
  return 0;
}
