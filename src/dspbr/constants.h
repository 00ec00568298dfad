// Mathematical constants of the reference (double precision), defined once.
#pragma once

namespace dspbr {

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace dspbr
