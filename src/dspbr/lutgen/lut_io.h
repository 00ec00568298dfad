// Files of the LUT toolchain (layout in docs/luts.md):
//  - EXR through OpenImageIO, one channel "Y", scanline 0 = index 0 of the slowest image axis,
//    columns = the fastest axis; 3D Base_E is one image per f0 slice (Base_<f0>_E.exr) and one
//    atlas of the slices stacked vertically (Base_E.exr); 16-bit PNGs (NAME.png); dspbr:* attributes.
//  - pbrlut.hpp: C/C++ header with the published symbol names (declarations always visible,
//    definitions under PBRLUT_IMPLEMENTATION, values printed with max_digits10 = 9 digits).
//  - dspbr_luts.json: axes, values (double), per-cell standard errors, integrator settings.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "dspbr/lutgen/generate.h"
#include "dspbr/tables/table_files.h"
#include "dspbr/tables/table.h"

namespace dspbr {

struct LutFormats {
  bool exr = true, hpp = true, json = true, png = true;
  bool half = false;  // EXR pixel type: half instead of 32-bit float
};

// File names (inside the output folder) of the EXR images of a table. Base_E slices are named by
// f0 with two decimals, or more when two slices would otherwise share a name.
std::vector<std::string> lut_exr_names(const Table& t);

// Writes the EXRs of `t` into dir (atomically, one file at a time), for a 3D table also the atlas
// (lut_atlas_name: the slices stacked vertically); returns the largest |stored - value| caused by
// the pixel type (float or half rounding).
// `command`: recorded as dspbr:command when not empty (the command that rewrites the files).
double write_lut_exrs(const Table& t, const std::string& dir, bool half, const std::string& command = "");
std::string lut_atlas_name(const Table& t);  // "" for 1D/2D tables

// 16-bit PNG of `t` (3D: the atlas), value = offset + scale * pixel / 65535 (dspbr:png_decode);
// returns the 16-bit rounding error.
std::vector<std::string> lut_png_names(const Table& t);
double write_lut_png(const Table& t, const std::string& dir, const std::string& command = "");

// Reads one single-channel "Y" EXR: width, height and the pixels row by row (as float).
std::vector<float> read_lut_exr(const std::string& path, int* width, int* height);

// The header text and the JSON text of a table set.
std::string lut_header_text(const std::vector<Table>& tables, const LutOptions& opt);
std::string lut_json_text(const std::vector<Table>& tables, const LutOptions& opt);

// Writes every requested format into dir (created when missing). Returns the largest EXR
// rounding error per table (same order as tables; 0 when no EXR was written).
std::vector<double> write_luts(const std::vector<Table>& tables, const LutOptions& opt, const std::string& dir,
                               const LutFormats& formats);

}  // namespace dspbr
