// libFuzzer target: material instance files (params/material_instance.h) checked against the
// built-in params-2025x.json and converted into a Material, as `dspbr eval --material` does.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>

#include "dspbr/io/read_file.h"
#include "dspbr/params/material_instance.h"
#include "dspbr/params/material_params.h"
#include "dspbr/params/param_defs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json doc = dspbr::parse_json(text, "fuzz.json", "material instance file");
    const auto& defs = dspbr::ParamDefs::builtin();
    if (dspbr::check_material_instance(defs, doc).empty()) {
      const dspbr::Material m = dspbr::material_from_instance(defs, doc);
      dspbr::validate_material(m);
    }
  } catch (const std::exception&) {
  }
  return 0;
}
