// The table sets of the conformance demonstrations (docs/conformance.md, "Demonstrations"): the
// reference BSDF reading other tables stands for an implementation that computes the energy terms
// another way.
//   renderer       the reference itself (the built-in renderer layout)
//   published      the published tables with their multilinear lookups (LutSet::published())
//   fits           the LUT-free fits of fits/dspbr_fits.hpp (float), sampled at the renderer
//                  layout's grid points (GGX_E, GGX_beta = E_5 / E_m - (1 - mu)^5, the averages,
//                  Sheen_E, Sheen_ash_E): what a renderer using the fits gets, plus the grid's
//                  interpolation error (2.5e-4 for GGX_E, docs/luts.md)
//   uncompensated  no energy compensation: E_m = E_m,avg = 1 (no multiple-scattering lobe, no F_ms
//                  term), E_b = 0 (no albedo scaling under the sheen); the Schlick moment beta,
//                  and with it the diffuse base's coupling to the specular albedo, unchanged
//   analytic       GGX_E and GGX_E_avg from Karis 2014's analytic environment BRDF at F_0 = 1
//                  (1 - 0.55 r): an implementation that approximates the albedo instead of reading it
#pragma once
#include <string>

#include "dspbr/tables/lut_set.h"

namespace dspbr::conformance {

enum class DemoTables { Renderer, Published, Fits, Uncompensated, Analytic };

// "renderer", "published", "fits", "uncompensated", "analytic"; parse throws std::invalid_argument for others.
const char* demo_tables_name(DemoTables t);
DemoTables parse_demo_tables(const std::string& name);

// The set (built once, cached; thread-safe).
const LutSet& demo_table_set(DemoTables t);

}  // namespace dspbr::conformance
