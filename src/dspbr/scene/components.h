// Components of textured materials and the tables a component mask needs (scene analysis); the
// component mask itself and the untextured active_components are in dspbr/component.h.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dspbr/component.h"
#include "dspbr/tables/lut_set.h"

namespace dspbr {

// Components whose weight can be non-zero somewhere on a textured material: `m` holds the values
// where the textures are 1, and each parameter in `scaled_by_texture` (float or colour ids, e.g.
// "metallic", "sheenColor") may take any value between 0 and its value in `m` (glTF textures
// multiply their factors). Other ids (normals, booleans, enums) are ignored. Every component's
// activity is monotone in each parameter, so the union over the 2^k corners of that box is exact.
uint32_t active_components(const Material& m, const std::vector<std::string>& scaled_by_texture);

// LUT tables (canonical names and order, lutgen/generate.h) the active components need; with
// transmission_compensation (beyond DSPBR 2025x, docs/bsdf.md) a volumetric transparent
// component also needs the four Glass tables (thin-walled glass needs only GGX_E / GGX_E_avg).
std::vector<std::string> tables_for_components(uint32_t mask, bool transmission_compensation = false);
// The same in a layout's names: the published layout as above; the renderer layout as the shader
// library binds them (shader_specialization.h's shader_textures: GGX_beta and GGX_B_avg for the
// opaque dielectric's base, both sheen tables), then the Glass tables with the compensation.
std::vector<std::string> tables_for_components(uint32_t mask, bool transmission_compensation, LutLayout layout);

}  // namespace dspbr
