#include "dspbr/vulkan/lookup_textures.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

#include "dspbr/tables/renderer_luts.h"

namespace vk_compute {

TableImage read_table_exr(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::invalid_argument("cannot read '" + path + "'");
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != 1) throw std::invalid_argument("'" + path + "' has more than one channel");
  TableImage t{spec.width, spec.height, std::vector<float>(size_t(spec.width) * size_t(spec.height))};
  if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, t.pixels.data()))
    throw std::invalid_argument("cannot read the pixels of '" + path + "'");
  return t;
}

std::vector<TableImage> read_lookup_textures(const std::string& lut_dir, bool glass) {
  // The binding order of the generated headers (their texture-mode comment blocks): the renderer
  // layout's canonical order.
  std::vector<TableImage> tables;
  for (const char* name : dspbr::RendererLuts::names()) tables.push_back(read_table_exr(lut_dir + "/renderer/" + name + ".exr"));
  if (glass)
    for (const char* name : dspbr::RendererLuts::glass_names())
      tables.push_back(read_table_exr(lut_dir + "/renderer/" + name + ".exr"));
  return tables;
}

}  // namespace vk_compute
