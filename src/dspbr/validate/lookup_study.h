// The accuracy of the tables at the point of use (`dspbr lut --bench`, docs/luts.md): what a
// renderer computes from each layout, against exact values from independent quadrature
// (validate/lut_reference.h) on random off-grid points of the whole domain (cos theta down to
// 1e-3, roughness down to 0.01, alpha_b down to 1/256, half of the points log-uniform towards
// those ends), and the white furnace of materials built from the lookups.
#pragma once
#include <string>
#include <vector>

#include "dspbr/tables/lut_set.h"

namespace dspbr::validate {

struct LookupErrorRow {
  std::string table, layout;
  size_t values = 0;   // stored values of the table in that layout
  double max = 0;      // max |lookup - exact| (relative where exact > 1)
  double rms = 0;
};

struct LookupFurnaceRow {
  std::string material, layout;
  double max_deviation = 0;  // max |albedo - 1| over roughness x cos grid (sheen: vs exact E_b)
};

struct LookupStudy {
  int points = 0;
  std::vector<LookupErrorRow> errors;
  std::vector<LookupFurnaceRow> furnace;
  // GGX_E in the published layout (cell-centred N x N, bilinear) at growing N: what size it
  // needs to match the renderer layout (built from the renderer lookups as the exact function).
  std::vector<LookupErrorRow> published_sizes;
};

// `published` and `renderer` must be LutSets of those layouts. Deterministic for a seed.
LookupStudy run_lookup_study(const LutSet& published, const LutSet& renderer, int points, uint64_t seed);

// Markdown tables of the study.
std::string lookup_study_markdown(const LookupStudy& s);

}  // namespace dspbr::validate
