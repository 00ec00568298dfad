// glTF materials mapped to DSPBR parameters: core metallic-roughness, the KHR_materials_*
// extensions and the 3DS_materials_* extensions (found under a material's "extensions" or its
// "extras"). The mapping, parameter by parameter, is written down in docs/gltf_mapping.md.
// Textures are reported (which DSPBR parameter they drive), not sampled: the mapped Material holds
// the factors, i.e. the values where the texture is 1.
#pragma once
#include <string>
#include <vector>

#include "dspbr/gltf/gltf_file.h"
#include "dspbr/material.h"

namespace dspbr::gltf {

struct TextureUse {
  std::string parameter;  // DSPBR parameter id it drives; "" when it has no DSPBR counterpart
  std::string source;     // glTF property, e.g. "KHR_materials_clearcoat.clearcoatTexture"
  int texture = -1;       // index into the glTF "textures" array
  // True when the texture scales the factor (value in [0, factor]); false when it replaces or
  // offsets it (normal maps, iridescence thickness between minimum and maximum).
  bool multiplies = true;
};

struct GltfMaterial {
  int index = -1;
  std::string name;           // the glTF name, or "material <index>" when it has none
  Material material;          // DSPBR parameters at texture value 1
  std::vector<TextureUse> textures;
  std::vector<std::string> notes;  // ignored extensions, values outside DSPBR ranges, ...

  // DSPBR parameter ids driven by a texture (each once, in order of appearance).
  std::vector<std::string> textured_parameters() const;
};

// Maps every entry of the asset's "materials" array. Throws std::runtime_error
// "<path>: materials[i] '<name>': <problem>" for a wrongly typed property (e.g. a string where a
// factor is expected, a colour with the wrong number of components) or a texture index that does
// not exist.
std::vector<GltfMaterial> map_materials(const GltfFile& file);

}  // namespace dspbr::gltf
