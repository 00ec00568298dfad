// libFuzzer target: glTF and GLB assets (gltf/gltf_file.h) and their materials mapped to DSPBR
// parameters (gltf/gltf_material.h), as `dspbr scene analyze` reads them. External buffers are
// looked up in a folder that does not exist.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>

#include "dspbr/gltf/gltf_file.h"
#include "dspbr/gltf/gltf_material.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const dspbr::gltf::GltfFile f = dspbr::gltf::parse_gltf(std::vector<std::uint8_t>(data, data + size),
                                                            "/nonexistent-fuzz-dir/fuzz.gltf");
    (void)dspbr::gltf::map_materials(f);
  } catch (const std::exception&) {
  }
  return 0;
}
