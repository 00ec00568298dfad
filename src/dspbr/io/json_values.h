// JSON arrays of the reference's value types, for the documents the tools write: an Rgb as
// [r, g, b] and a Vec3 as [x, y, z].
#pragma once
#include <nlohmann/json.hpp>

#include "dspbr/vec3.h"

namespace dspbr {

inline nlohmann::json rgb_json(const Rgb& c) { return nlohmann::json::array({c.r, c.g, c.b}); }
inline nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

}  // namespace dspbr
