// `dspbr scene analyze SCENE [--json] [--parameters]`: per material of a glTF scene (.gltf/.glb)
// or material instance file, the active DSPBR components and the LUT tables they need.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "commands.h"
#include "provenance.h"
#include "dspbr/io/json_write.h"
#include "dspbr/params/material_params.h"
#include "dspbr/scene/components.h"
#include "dspbr/scene/scene_analysis.h"

namespace dspbr::cli {

namespace {

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s.empty() ? "(none)" : s;
}

}  // namespace

void add_scene_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("scene", "glTF scenes: which DSPBR components and tables their materials need");
  cmd->require_subcommand(1);
  struct Options {
    std::string path;
    bool json = false, parameters = false, compensation = false;
  };
  auto opt = std::make_shared<Options>();
  auto* analyze = cmd->add_subcommand("analyze", "Per material: active components, needed tables, textured parameters");
  analyze->add_option("SCENE", opt->path, ".gltf, .glb or material instance .json")->required();
  analyze->add_flag("--json", opt->json,
                    "Print {\"materials\": [{\"name\", \"components\", \"tables\", \"textured\", \"notes\"}], \"tables\", \"warnings\"}");
  analyze->add_flag("--parameters", opt->parameters, "Also print each material's mapped DSPBR parameters");
  analyze->add_flag("--transmission-compensation", opt->compensation,
                    "List the tables a renderer with the rough-transmission compensation needs (beyond DSPBR 2025x: "
                    "the Glass tables for volumetric transparent materials)");
  analyze->callback([opt] {
    SceneAnalysis s;
    try {
      s = analyze_scene(opt->path, opt->compensation);
    } catch (const std::runtime_error& e) {
      throw UsageError(e.what());
    }
    if (opt->json) {
      auto doc = scene_analysis_json(s, opt->parameters);
      doc["provenance"] = output_provenance();
      std::cout << json_text(doc, 2, "scene analyze --json") << "\n";
      return;
    }
    std::printf("%s: %zu material(s)\n", s.path.c_str(), s.materials.size());
    for (const auto& w : s.warnings) std::printf("  warning: %s\n", w.c_str());
    for (const auto& m : s.materials) {
      std::printf("  %s\n", m.name.c_str());
      std::printf("    components: %s\n", joined(component_names(m.components)).c_str());
      std::printf("    tables:     %s\n", joined(m.tables).c_str());
      for (const auto& t : m.texture_sources) std::printf("    textured:   %s\n", t.c_str());
      for (const auto& n : m.notes) std::printf("    note:       %s\n", n.c_str());
      if (opt->parameters)
        for (const auto& id : material_parameter_ids())
          std::printf("    %-28s %s\n", id.c_str(), get_material_parameter(m.material, id).dump().c_str());
    }
    std::printf("tables needed by the scene: %s\n", joined(s.tables).c_str());
  });
}

}  // namespace dspbr::cli
