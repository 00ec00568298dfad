// libFuzzer target: parameter definition files (params/param_defs.h), read as `dspbr params`
// reads them, then every material printed as `dspbr params show --json` prints it.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>

#include "dspbr/io/read_file.h"
#include "dspbr/params/param_defs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto doc = dspbr::parse_json<nlohmann::ordered_json>(text, "fuzz.json", "parameter definition file");
    const dspbr::ParamDefs defs = dspbr::ParamDefs::from_json(doc, "fuzz.json");
    for (const auto& id : defs.material_ids()) (void)dspbr::material_def_to_json(defs.material(id)).dump(2);
  } catch (const std::exception&) {
    // a one-line error: what hostile input should give
  }
  return 0;
}
