// Which DSPBR components and tables a scene's materials need (materials/scenes issue).
#pragma once
#include <string>
#include <vector>

namespace dspbr {

// Names of the LUT tables (GGX_E, GGX_E_avg, Base_E, Base_E_avg, Sheen_E, Sheen_ash_E) that the
// materials of the scene at `path` (.gltf/.glb or a material instance .json) need, in the
// canonical table order. Throws std::runtime_error with a message naming the file on bad input.
std::vector<std::string> tables_for_scene(const std::string& path);

}  // namespace dspbr
