// Files of the renderer layout (docs/luts.md, "Renderer layout" and "GPU-ready files"):
//  - dspbr_renderer_luts.json: axes with warps, encodings, stored values (float-exact doubles),
//    per-sample standard errors, integrator settings;
//  - per table NAME.exr (32-bit float or half, channel Y) and NAME.png (16-bit grey, value =
//    offset + scale * pixel / 65535), each with its axes, warps, grid, encoding and decoding as
//    image attributes ("dspbr:*"), so that a file explains itself;
//  - dspbr_split_sum.exr / .png: the split-sum table for image-based lighting on a plain
//    cell-centred grid (columns cos theta, rows roughness): R = A = E_m, G = the Schlick moment B
//    (DFG-style IBL: specular = f0 (A - B) + f90 B), B = the main sheen's albedo at alpha_b = r^2,
//    sampled from the renderer lookups.
#pragma once
#include <string>
#include <string_view>

#include "dspbr/lutgen/generate.h"
#include "dspbr/tables/table_files.h"
#include "dspbr/tables/renderer_luts.h"

namespace dspbr {

std::string renderer_json_text(const RendererLuts& luts, const LutOptions& opt, int scale);

// Writes NAME.exr (float, or half) and NAME.png per table and the split-sum images into dir
// (atomically); `command` is recorded as dspbr:command when not empty.
constexpr int kSplitSumSize = 64;  // the split-sum image's rows and columns
void write_renderer_images(const RendererLuts& luts, const std::string& dir, bool half = false,
                           int split_sum_size = kSplitSumSize, const std::string& command = "");

// The split-sum table (rows roughness, columns cos theta, cell-centred, 3 channels interleaved).
std::vector<float> split_sum_pixels(const RendererLuts& luts, int size);

}  // namespace dspbr
