// Which DSPBR components and tables a scene's materials need.
// A scene is a glTF asset (.gltf / .glb, materials mapped as in docs/gltf_mapping.md) or a single
// material instance file ({"material": ..., "values": {...}}, see params/material_instance.h).
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dspbr/material.h"
#include "dspbr/tables/lut_set.h"

namespace dspbr {

struct MaterialAnalysis {
  std::string name;
  Material material;                     // DSPBR parameters (glTF: at texture value 1)
  std::vector<std::string> textured;     // DSPBR parameters driven by a texture
  std::vector<std::string> texture_sources;  // "<parameter> <- <glTF property> (texture i)"
  std::vector<std::string> notes;        // mapping remarks (ignored extensions, ranges)
  uint32_t components = 0;               // active_components, textured ones possibly non-zero
  std::vector<std::string> tables;       // tables_for_components(components)
};

struct SceneAnalysis {
  std::string path;
  std::vector<MaterialAnalysis> materials;
  uint32_t components = 0;           // union over the materials
  std::vector<std::string> tables;   // union, canonical table order
  std::vector<std::string> warnings; // file-level findings (e.g. buffers not fetched)
  bool transmission_compensation = false;  // as analysed (the tables above include the Glass ones)
  // Findings about the materials a pipeline should act on (`scene analyze --strict`): every
  // material's notes (unmapped extensions, values outside DSPBR's ranges, approximate mappings).
  // The file's warnings (e.g. geometry not fetched) do not change a material and are not counted.
  std::size_t findings() const;
};

// Analyses the scene at `path`. A glTF mesh primitive without a material adds glTF's default
// material ("(default material)"). Throws std::runtime_error with a message naming the file on
// bad input (unreadable, malformed JSON, truncated .glb, missing buffer, wrong types, invalid
// instance).
// transmission_compensation: the tables a renderer with the transmission compensation needs
// (tables_for_components).
SceneAnalysis analyze_scene(const std::string& path, bool transmission_compensation = false);

// The analysis as JSON, as `dspbr scene analyze --json` prints it: {"path", "materials": [{"name",
// "components", "tables", "textured", "notes"[, "parameters": {id: value}]}], "tables", "warnings",
// "findings"}, the tables named in `layout`.
nlohmann::ordered_json scene_analysis_json(const SceneAnalysis& s, bool parameters = false,
                                           LutLayout layout = LutLayout::Published);

// Names of the LUT tables (GGX_E, GGX_E_avg, Base_E, Base_E_avg, Sheen_E, Sheen_ash_E, Glass_*) that the
// materials of the scene at `path` (.gltf/.glb or a material instance .json) need, in the
// canonical table order. Throws std::runtime_error with a message naming the file on bad input.
std::vector<std::string> tables_for_scene(const std::string& path, bool transmission_compensation = false);

}  // namespace dspbr
