// The shader library specialised for a set of DSPBR components (docs/renderer.md, "Only what a
// scene needs"): the header `dspbr shader` writes, which sets the library's DSPBR_HAS_<COMPONENT>
// switches (shaders/dspbr/features.glsl) so that the compiler drops the lobes and tables the
// scene's materials do not use, and the lookup textures those components read.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace dspbr {

// The components the library can compile out, in features.glsl's order: the BSDF's components
// (component.h) without the volume's, which are the integrator's.
const std::vector<uint32_t>& shader_components();

// The renderer-layout tables the library reads for these components, with their texture index in
// dspbr_lookup.glsl / .hlsl (binding DSPBR_LOOKUP_BINDING_BASE + index, register t<index>).
struct ShaderTexture {
  std::string table;
  int index;
};
std::vector<ShaderTexture> shader_textures(uint32_t components);

// dspbr_specialization.h for `components` (DSPBR_HAS_<NAME> 1 for each of them, 0 for the
// others); `source` says where they come from (a scene file, a list), written in its comment.
std::string shader_specialization_header(uint32_t components, const std::string& source);

}  // namespace dspbr
