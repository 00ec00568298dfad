// libFuzzer property target: every function of the generated lookup headers (luts/dspbr_lookup.h,
// luts/dspbr_glass_lookup.h: what a renderer includes) on fuzzed float arguments, NaN, infinities,
// subnormals and huge values included (docs/luts.md, "Limits"). UndefinedBehaviorSanitizer
// reports an out-of-range float-to-int conversion, AddressSanitizer a read outside a table; the
// target aborts when a result is NaN, infinite or negative (the cubic's undershoot where a table
// approaches 0 is clamped: Base_E at f0 = 0 dipped to -3.5e-4 before, docs/luts.md "Limits").
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

// clang-format off: the glass header uses the main one's helpers.
#include "dspbr_lookup.h"
#include "dspbr_glass_lookup.h"
// clang-format on

namespace {

struct Floats {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  float next() {  // the next 4 bytes as a float (0 once the input is used up)
    float f = 0;
    if (at + 4 <= size) std::memcpy(&f, data + at, 4);
    at += 4;
    return f;
  }
};

void check(float r) {
  if (!std::isfinite(r) || r < 0.0f) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Floats in{data, size};
  const float a = in.next(), b = in.next(), c = in.next(), d = in.next(), e = in.next();
  const int inside = in.next() > 0.5f ? 1 : 0, transmission = in.next() > 0.5f ? 1 : 0;
  check(dspbr_ggx_E(a, b));
  check(dspbr_ggx_E_avg(a));
  check(dspbr_ggx_E_avg_missing(a));
  check(dspbr_fresnel_ms(a, b, c));
  check(dspbr_base_E(a, b, c));
  check(dspbr_base_E_avg(a, b));
  check(dspbr_sheen_E(a, b));
  check(dspbr_sheen_ash_E(a, b));
  check(dspbr_ms_lobe(a, b, c));
  check(dspbr_diffuse_bc(a, b, c, d));
  check(dspbr_sheen_layer_scale(a, b, c, d));
  check(dspbr_sheen_ash_layer_scale(a, b, c, d));
  check(dspbr_glass_f0(a));
  check(dspbr_glass_E(a, b, c, inside));
  check(dspbr_glass_E_avg(a, b, inside));
  check(dspbr_glass_core_E(a, b, c, inside));
  check(dspbr_glass_core_E_avg(a, b, inside));
  check(dspbr_glass_transmission_share(a, b, inside));
  check(dspbr_glass_compensation(a, b, c, d, inside, transmission));
  check(dspbr_thin_glass_compensation(a, b, c, e, transmission));
  return 0;
}
