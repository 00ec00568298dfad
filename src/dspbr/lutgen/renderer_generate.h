// Generates the renderer layout (tables/renderer_luts.h): the directional tables are integrated at
// their samples with the integrators of lutgen/albedo.h (per-sample streams, so the result does not
// depend on the thread count), rounded to float (what every file holds), and the averages are
// then integrated from the float tables' own interpolants (Gauss-Legendre per grid cell in the
// warped cos coordinate), so that they are the cosine averages of the lookups.
#pragma once
#include "dspbr/lutgen/generate.h"
#include "dspbr/tables/renderer_luts.h"

namespace dspbr {

// Integrator settings, seed and threads from `opt` (its sizes are ignored; its table list only
// says whether the glass tables are made: when it holds Glass_E); axes from
// renderer_default_axes(name, scale).
RendererLuts generate_renderer_luts(const LutOptions& opt, int scale = 1);

// Adds the glass tables (renderer_default_axes(name, scale)) to a set.
void add_renderer_glass_luts(RendererLuts& luts, const LutOptions& opt, int scale = 1);

// The averages of an already filled GGX_E / GGX_beta pair (used by the generator; exposed for
// the tests, which check them against an independent integration).
void fill_renderer_averages(RendererLuts& luts);
// The glass averages (Glass_E_avg, Glass_inv_E_avg) of filled Glass_E / Glass_inv_E tables, the
// same way: cosine averages of the lookups.
void fill_renderer_glass_averages(RendererLuts& luts);

}  // namespace dspbr
