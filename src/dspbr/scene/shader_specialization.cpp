#include "dspbr/scene/shader_specialization.h"

#include <algorithm>
#include <cctype>

#include "dspbr/component.h"
#include "dspbr/io/message.h"
#include "dspbr/tables/renderer_luts.h"
#include "dspbr/tables/table_registry.h"
#include "dspbr/version.h"

namespace dspbr {

const std::vector<uint32_t>& shader_components() {
  static const std::vector<uint32_t> list = {kMetallic,   kOpaqueDielectric, kThinTransparent, kVolumetricTransparent,
                                             kTranslucency, kThinFilm,      kSheen,           kFlakes,
                                             kClearcoat,  kEmission,         kDispersion};
  return list;
}

std::vector<ShaderTexture> shader_textures(uint32_t c) {
  // Every core lobe (metal, dielectric, transparent) has the multiple-scattering term: E_m and
  // its average. The opaque dielectric's B_c reads E(mu; r, f0) = f0 E_m + (1 - f0) beta E_m +
  // F_ms (1 - E_m) and its average (GGX_beta, GGX_B_avg); the sheen's layering reads E_b of the
  // model chosen at run time (both tables). The texture index is the table's place in the
  // generated lookup (RendererLuts::names(), the order of dspbr_lookup.glsl's bindings).
  const bool core = c & (kMetallic | kOpaqueDielectric | kThinTransparent | kVolumetricTransparent);
  const bool base = c & kOpaqueDielectric, sheen = c & kSheen;
  std::vector<ShaderTexture> t;
  const std::vector<const char*>& order = RendererLuts::names();
  for (int k = 0; k < int(order.size()); ++k) {
    const std::string name = order[size_t(k)];
    const bool needed = ((name == lut_name(Lut::GgxE) || name == lut_name(Lut::GgxEAvg)) && core) ||
                        ((name == lut_name(Lut::GgxBeta) || name == lut_name(Lut::GgxBAvg)) && base) ||
                        ((name == lut_name(Lut::SheenE) || name == lut_name(Lut::SheenAshE)) && sheen);
    if (needed) t.push_back({name, k});
  }
  return t;
}

std::string shader_specialization_header(uint32_t components, const std::string& source) {
  std::string kept, dropped;
  for (uint32_t c : shader_components()) {
    std::string& list = (components & c) ? kept : dropped;
    list += (list.empty() ? "" : ", ") + std::string(component_name(Component(c)));
  }
  // source may hold a file name: every byte outside printable ASCII written \xNN, so that it
  // cannot end the comment (a newline); the line ends in '.', so a backslash cannot continue it.
  std::string h = "// dspbr_specialization.h: the DSPBR shader library specialised for " + quote_input(source) + ".\n";
  h += "// Written by `dspbr shader` (dspbr " + std::string(project_version()) + "); include it before dspbr.h, dspbr.glsl or\n";
  h += "// dspbr.hlsl (docs/renderer.md, \"Only what a scene needs\").\n";
  h += "// Compiled in: " + (kept.empty() ? std::string("(none)") : kept) + ".\n";
  h += "// Compiled out: " + (dropped.empty() ? std::string("(none)") : dropped) +
       " (a material that uses one is evaluated without it).\n";
  const std::vector<ShaderTexture> tex = shader_textures(components);
  h += "// Lookup textures to bind (GLSL binding DSPBR_LOOKUP_BINDING_BASE + n, HLSL register tn):";
  if (tex.empty()) h += " none";
  h += "\n";
  for (const ShaderTexture& t : tex)
    h += "//   " + std::to_string(t.index) + "  dspbr_" + t.table + "_tex  (luts/renderer/" + t.table + ".exr)\n";
  h += "#ifndef DSPBR_SPECIALIZATION_H\n#define DSPBR_SPECIALIZATION_H\n";
  for (uint32_t c : shader_components()) {
    std::string name = component_name(Component(c));
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char ch) { return char(std::toupper(ch)); });
    h += "#define DSPBR_HAS_" + name + ((components & c) ? " 1\n" : " 0\n");
  }
  h += "#endif\n";
  return h;
}

}  // namespace dspbr
