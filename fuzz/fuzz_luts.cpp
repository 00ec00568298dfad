// libFuzzer target: table files of both layouts (tables/lut_set.h, lutgen/lut_io.h), read as
// `dspbr validate --luts` reads them; every table read is looked up once at its domain's centre
// and corners (an index outside the values would be reported by AddressSanitizer).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>
#include <vector>

#include "dspbr/lutgen/lut_io.h"
#include "dspbr/tables/lut_set.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const dspbr::LutSet set = dspbr::LutSet::from_text(text, "fuzz.json");
    if (set.layout == dspbr::LutLayout::Renderer) (void)set.E_m(0.5, 0.5), (void)set.E_sheen(0.0, 1.0);
  } catch (const std::exception&) {
  }
  try {
    for (const dspbr::Table& t : dspbr::read_lut_json_text(text, "fuzz.json"))
      for (double x : {0.0, 0.5, 1.0}) (void)t.lookup(std::vector<double>(t.axes.size(), x));
  } catch (const std::exception&) {
  }
  return 0;
}
