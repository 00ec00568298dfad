#include "dspbr/validate/waivers.h"

#include <cmath>

#include "dspbr/tables/table_registry.h"

namespace dspbr::validate {

namespace {
const char* kConservation = "furnace: conservation (E <= 1 + tol)";
const char* kClampReason =
    "DSPBR's published table layout clamps at its first cell centre: below cos θ_v = 1/(2N) the table value is "
    "held at the first cell, so the compensation computed from it is too small at grazing view";
}  // namespace

const std::vector<Waiver>& dspbr_waivers() {
  static const std::vector<Waiver> list = {
      {"table-clamp-base", kConservation, "opaque dielectric s=1 r=0", lut_name(Lut::BaseE), kClampReason,
       "spec 'Diffuse BRDF' (B_c from the Base_E table) and the table layout of docs/luts.md"},
      {"table-clamp-sheen", kConservation, "white sheen over white base*", lut_name(Lut::SheenE), kClampReason,
       "spec 'Sheen' (base scaled by min(1 - E_b(v), 1 - E_b(l)) from the Sheen_E table) and docs/luts.md"},
      {"alternative-sheen-gain", kConservation, "white sheen (alternative visibility)*", "",
       "the [NP13] visibility of the alternative sheen gains energy, most at grazing view and low sheen roughness",
       "spec 'Alternative Sheen BRDF', figure white-furnace-sheen-ash-e: 'red pixels indicate energy gain'"},
  };
  return list;
}

bool waiver_applies(const Waiver& w, const std::string& check, const std::string& name, double cos,
                    const LutSet* luts) {
  if (w.check != check) return false;
  const bool prefix = !w.cases.empty() && w.cases.back() == '*';
  const std::string stem = prefix ? w.cases.substr(0, w.cases.size() - 1) : w.cases;
  if (prefix ? name.rfind(stem, 0) != 0 : name != stem) return false;
  if (w.below_first_cell_of.empty()) return true;
  if (!luts) return false;
  const Table* t = nullptr;
  for (const Table* c : {&luts->ggx_e, &luts->base_e, &luts->sheen_e, &luts->sheen_ash_e})
    if (c->name == w.below_first_cell_of) t = c;
  if (!t || t->axes.empty()) return false;
  return std::abs(cos) < t->axes.back().coord(0);
}

}  // namespace dspbr::validate
