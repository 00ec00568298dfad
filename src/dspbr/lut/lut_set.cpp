#include "dspbr/lut/lut_set.h"

#include "dspbr/lut/lut_io.h"

namespace dspbr {

LutSet LutSet::load(const std::string& json_path) {
  LutSet set;
  for (Table& t : read_lut_json(json_path)) {
    if (t.name == "GGX_E") set.ggx_e = std::move(t);
    else if (t.name == "GGX_E_avg") set.ggx_e_avg = std::move(t);
    else if (t.name == "Base_E") set.base_e = std::move(t);
    else if (t.name == "Base_E_avg") set.base_e_avg = std::move(t);
    else if (t.name == "Sheen_E") set.sheen_e = std::move(t);
    else if (t.name == "Sheen_ash_E") set.sheen_ash_e = std::move(t);
  }
  return set;
}

const LutSet& LutSet::builtin() {
  // Function-local static: initialised once, thread-safe (C++11 magic statics).
  static const LutSet set = load(DSPBR_SOURCE_DIR "/luts/dspbr_luts.json");
  return set;
}

}  // namespace dspbr
