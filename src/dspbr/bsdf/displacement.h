// Displacement: p' = p + t h_x + b h_y + n h_z (spec "Displacement").
#pragma once
#include "dspbr/frame.h"
#include "dspbr/material.h"
#include "dspbr/vec3.h"

namespace dspbr {

// Displaced position of p by h given in the tangent frame (t, b, n) of the surface at p (all in
// the same space, e.g. object space). The frame is the mesh's tangent frame (t' along the texture's
// u axis, b = n x t'), without the anisotropy rotation: see docs/components.md.
Vec3 displaced_position(const Vec3& p, const Frame& tangent_frame, const Vec3& h);
inline Vec3 displaced_position(const Vec3& p, const Frame& tangent_frame, const Material& m) {
  return displaced_position(p, tangent_frame, m.displacement);
}

}  // namespace dspbr
