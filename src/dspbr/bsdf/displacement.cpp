#include "dspbr/bsdf/displacement.h"

namespace dspbr {

Vec3 displaced_position(const Vec3& p, const Frame& f, const Vec3& h) {
  return p + f.t * h.x + f.b * h.y + f.n * h.z;  // spec "Displacement"
}

}  // namespace dspbr
