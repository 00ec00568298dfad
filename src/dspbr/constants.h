// Mathematical constants of the reference (double precision), defined once. Included by .cpp files
// (and tests), not by headers that bsdf/ and lut/ include: those folders still define their own.
#pragma once

namespace dspbr {

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace dspbr
