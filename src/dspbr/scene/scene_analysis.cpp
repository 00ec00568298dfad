#include "dspbr/scene/scene_analysis.h"

#include <stdexcept>

namespace dspbr {

std::vector<std::string> tables_for_scene(const std::string& path) {
  throw std::runtime_error("scene analysis is not implemented yet (" + path + ")");
}

}  // namespace dspbr
