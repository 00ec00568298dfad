// The tables of the generated lookups (luts/dspbr_lookup.glsl, dspbr_glass_lookup.glsl) in
// texture mode: each renderer-layout table read from LUT_DIR/renderer/NAME.exr (written by
// `dspbr lut`, one channel) as the pixels of an R32F image, uploaded as they are (width = the
// fastest axis, row 0 = index 0 of the slowest), in the headers' binding order (docs/luts.md,
// "Using the tables in your renderer").
#pragma once
#include <string>
#include <vector>

namespace vk_compute {

// One single-channel float image, row by row.
struct TableImage {
  int width = 0, height = 0;
  std::vector<float> pixels;
};

// One table image from an EXR of one channel; std::invalid_argument when unreadable.
TableImage read_table_exr(const std::string& path);

// The tables of dspbr_lookup.glsl (bindings 0-5 after DSPBR_LOOKUP_BINDING_BASE), followed with
// `glass` by those of dspbr_glass_lookup.glsl (6-9), read from lut_dir/renderer/.
std::vector<TableImage> read_lookup_textures(const std::string& lut_dir, bool glass);

}  // namespace vk_compute
