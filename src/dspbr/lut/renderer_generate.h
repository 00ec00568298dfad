// Generates the renderer layout (lut/renderer_luts.h): the directional tables are integrated at
// their samples with the integrators of lut/albedo.h (per-sample streams, so the result does not
// depend on the thread count), rounded to float (what every file holds), and the averages are
// then integrated from the float tables' own interpolants (Gauss-Legendre per grid cell in the
// warped cos coordinate), so that they are the cosine averages of the lookups.
#pragma once
#include "dspbr/lut/generate.h"
#include "dspbr/lut/renderer_luts.h"

namespace dspbr {

// Integrator settings, seed and threads from `opt` (its table list and sizes are ignored);
// axes from renderer_default_axes(name, scale).
RendererLuts generate_renderer_luts(const LutOptions& opt, int scale = 1);

// The averages of an already filled GGX_E / GGX_beta pair (used by the generator; exposed for
// the tests, which check them against an independent integration).
void fill_renderer_averages(RendererLuts& luts);

}  // namespace dspbr
