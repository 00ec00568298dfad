// Known failures caused by DSPBR itself (the spec's formulas or its published table layout), not
// by this implementation. A failed verdict that matches a waiver is reported as WAIVED with the
// waiver's reason and spec passage; it does not make `dspbr validate` fail. The list is data:
// dspbr_waivers() in waivers.cpp. A waiver that no verdict needed is reported as unused.
#pragma once
#include <string>
#include <vector>

#include "dspbr/tables/lut_set.h"

namespace dspbr::validate {

struct Waiver {
  std::string id;     // short label, e.g. "table-clamp-base"
  std::string check;  // the verdict's check name (exact)
  std::string cases;  // case name; a trailing '*' matches every case starting with the rest
  // Only below the first cell centre of this table's cos_theta axis ("" = at every view).
  std::string below_first_cell_of;
  std::string reason;  // why DSPBR itself fails here
  std::string spec;    // the spec passage
};

const std::vector<Waiver>& dspbr_waivers();

// Whether `w` covers a verdict of `check` on case `name` at view cosine `cos` (tables: for
// below_first_cell_of; null = no table bound known, the waiver does not apply).
bool waiver_applies(const Waiver& w, const std::string& check, const std::string& name, double cos,
                    const LutSet* luts);

}  // namespace dspbr::validate
