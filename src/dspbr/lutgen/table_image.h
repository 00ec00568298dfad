// Image files of the tables (EXR and 16-bit PNG through OpenImageIO): written atomically, no
// time stamp (same tables, same bytes), marked as data (linear), with the tables' own "dspbr:*"
// attributes so that a file explains itself.
#pragma once
#include <OpenImageIO/typedesc.h>

#include <string>
#include <utility>
#include <vector>

namespace dspbr {

using ImageAttributes = std::vector<std::pair<std::string, std::string>>;

// Writes `channels` interleaved float pixels (row 0 first) to path (.exr or .png by its name)
// with pixel type `type` (FLOAT, HALF, UINT16). PNG values are clamped to [0, 1] by the writer.
void write_table_image(const std::string& path, const std::vector<float>& px, int width, int height, int channels,
                       OIIO::TypeDesc type, const ImageAttributes& attrs);

// A 16-bit PNG of single-channel values: pixel = (v - lo) / (hi - lo) * 65535 with lo, hi the
// values' range; adds the decoding as the "dspbr:png_decode" attribute. Returns the largest
// |decoded - value| (16-bit rounding).
double write_table_png(const std::string& path, const std::vector<double>& values, int width, int height,
                       ImageAttributes attrs);

}  // namespace dspbr
