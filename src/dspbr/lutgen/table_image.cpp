#include "dspbr/lutgen/table_image.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dspbr/io/atomic_file.h"
#include "dspbr/version.h"

namespace dspbr {

void write_table_image(const std::string& path, const std::vector<float>& px, int width, int height, int channels,
                       OIIO::TypeDesc type, const ImageAttributes& attrs) {
  const bool exr = path.size() > 4 && path.substr(path.size() - 4) == ".exr";
  write_atomically(path, [&](const std::string& tmp) {
    auto out = OIIO::ImageOutput::create(path);  // format from the final name (.exr / .png)
    if (!out) throw std::runtime_error("cannot create an image writer for '" + path + "': " + OIIO::geterror());
    OIIO::ImageSpec spec(width, height, channels, type);
    if (channels == 1) spec.channelnames = {"Y"};
    if (exr) spec.attribute("compression", "zip");
    // OIIO stamps the current time unless DateTime is set; an empty one is not written.
    spec.attribute("DateTime", "");
    // The project version alone (version.h): committed tables stay byte-identical across commits.
    spec.attribute("Software", std::string("dspbr lut ") + project_version());
    spec.attribute("oiio:ColorSpace", "Linear");  // data, not colour: no gamma tag
    for (const auto& [k, v] : attrs) spec.attribute(k, v);
    if (!out->open(tmp, spec)) throw std::runtime_error("cannot write '" + path + "': " + out->geterror());
    if (!out->write_image(OIIO::TypeDesc::FLOAT, px.data()))
      throw std::runtime_error("cannot write '" + path + "': " + out->geterror());
    if (!out->close()) throw std::runtime_error("cannot write '" + path + "': " + out->geterror());
  });
}

double write_table_png(const std::string& path, const std::vector<double>& values, int width, int height,
                       ImageAttributes attrs) {
  double lo = 1e300, hi = -1e300;
  for (double v : values) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  const double scale = hi > lo ? hi - lo : 1.0;
  std::vector<float> unit(values.size());
  double rounding = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    unit[i] = float((values[i] - lo) / scale);
    const double stored = std::round(double(unit[i]) * 65535.0) / 65535.0 * scale + lo;
    rounding = std::max(rounding, std::abs(stored - values[i]));
  }
  attrs.push_back({"dspbr:png_decode", fmt::format("value = {:.9g} + {:.9g} * pixel / 65535", lo, scale)});
  write_table_image(path, unit, width, height, 1, OIIO::TypeDesc::UINT16, attrs);
  return rounding;
}

}  // namespace dspbr
