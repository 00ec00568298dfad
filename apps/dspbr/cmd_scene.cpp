// `dspbr scene analyze SCENE... [--json] [--parameters] [--layout L] [--strict]`: per material of
// glTF scenes (.gltf/.glb, or a folder of them) or material instance files, the active DSPBR
// components and the tables they need; with several scenes a summary of what a renderer must
// implement. --strict exits 1 on findings (docs/gltf_mapping.md, "scene analyze").
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "commands.h"
#include "provenance.h"
#include "dspbr/gltf/gltf_file.h"
#include "dspbr/io/json_write.h"
#include "dspbr/limits.h"
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

// The scene files SCENE names: the file, or a folder's .gltf and .glb entries (sorted by name; an
// empty folder is an error). Every entry so named is read, so that one that is not a regular
// file (a FIFO, a folder, a looping link) is refused by the reader, as conformance generate --scenes
// refuses it, instead of being skipped without a word.
std::vector<std::string> scene_files(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return {path};
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(path, ec)) {
    const std::string ext = gltf::lower_extension(e.path().string());
    if (ext == ".gltf" || ext == ".glb") out.push_back(e.path().string());
  }
  if (ec) throw UsageError(path + ": cannot list the folder: " + ec.message());
  std::sort(out.begin(), out.end());
  if (out.empty()) throw UsageError(path + ": a folder without .gltf or .glb files");
  return out;
}

struct AnalyzeOptions {
  std::vector<std::string> paths;
  bool json = false, parameters = false, compensation = false, strict = false;
  std::string layout = "renderer";
};

// What a renderer must implement for all the scenes: components, parameter-level features and
// textured parameters (each with the number of materials), the tables, the findings.
nlohmann::ordered_json summary_json(const std::vector<SceneAnalysis>& scenes, LutLayout layout, bool compensation) {
  std::map<std::string, int> features, textured;
  uint32_t components = 0;
  std::size_t materials = 0, findings = 0;
  for (const SceneAnalysis& s : scenes) {
    components |= s.components;
    findings += s.findings();
    for (const MaterialAnalysis& m : s.materials) {
      ++materials;
      const auto has = [&](const char* id) { return std::count(m.textured.begin(), m.textured.end(), id) > 0; };
      if (m.material.anisotropy > 0 || has("anisotropy")) ++features["anisotropy"];
      if ((m.material.anisotropy > 0 && m.material.anisotropyRotation != 0) || has("anisotropyRotation"))
        ++features["anisotropy rotation"];
      if (m.material.thinWalled && m.material.transparency > 0) ++features["thin-walled transparency"];
      if (has("normal") || has("clearcoatNormal")) ++features["normal maps"];
      if (m.material.emissionValue > 0 && m.material.emissionMode == EmissionMode::LuminousPower)
        ++features["emission in luminous power (needs object area)"];
      for (const std::string& t : m.textured) ++textured[t];
    }
  }
  nlohmann::ordered_json out;
  out["scenes"] = scenes.size();
  out["materials"] = materials;
  out["components"] = component_names(components);
  out["features"] = features;
  out["textured"] = textured;
  out["layout"] = layout == LutLayout::Renderer ? "renderer" : "published";
  out["tables"] = tables_for_components(components, compensation, layout);
  out["findings"] = findings;
  return out;
}

void run_analyze(const AnalyzeOptions& opt) {
  const LutLayout layout = opt.layout == "published" ? LutLayout::Published : LutLayout::Renderer;
  std::vector<std::string> files;
  for (const std::string& p : opt.paths)
    for (std::string& f : scene_files(p)) files.push_back(std::move(f));
  std::vector<SceneAnalysis> scenes;
  std::size_t materials = 0;  // of the run: its analyses are kept until printed (limits.h)
  for (const std::string& f : files) {
    try {
      scenes.push_back(analyze_scene(f, opt.compensation));
    } catch (const std::runtime_error& e) {
      throw UsageError(e.what());
    }
    if ((materials += scenes.back().materials.size()) > limits::kSceneMaterials)
      throw UsageError(f + ": the run's scenes hold more than " + std::to_string(limits::kSceneMaterials) +
                       " materials, the limit of one run (docs/limits.md); analyze them in several runs");
  }
  const bool several = files.size() > 1 || opt.paths.size() > 1;
  const nlohmann::ordered_json summary = summary_json(scenes, layout, opt.compensation);
  if (opt.json) {
    // One scene: its document; several: {"scenes": [...], "summary": {...}}.
    nlohmann::ordered_json doc;
    if (several) {
      doc["scenes"] = nlohmann::ordered_json::array();
      for (const SceneAnalysis& s : scenes) doc["scenes"].push_back(scene_analysis_json(s, opt.parameters, layout));
      doc["summary"] = summary;
    } else {
      doc = scene_analysis_json(scenes[0], opt.parameters, layout);
    }
    doc["provenance"] = output_provenance();
    std::cout << json_text(doc, 2, "scene analyze --json") << "\n";
  } else {
    for (const SceneAnalysis& s : scenes) {
      std::printf("%s: %zu material(s)\n", quote_input(s.path).c_str(), s.materials.size());
      for (const auto& w : s.warnings) std::printf("  warning: %s\n", quote_input(w).c_str());
      for (const auto& m : s.materials) {
        std::printf("  %s\n", quote_input(m.name).c_str());
        std::printf("    components: %s\n", joined(component_names(m.components)).c_str());
        std::printf("    tables:     %s\n", joined(tables_for_components(m.components, opt.compensation, layout)).c_str());
        for (const auto& t : m.texture_sources) std::printf("    textured:   %s\n", quote_input(t).c_str());
        for (const auto& n : m.notes) std::printf("    note:       %s\n", quote_input(n).c_str());
        if (opt.parameters)
          for (const auto& id : material_parameter_ids())
            std::printf("    %-28s %s\n", id.c_str(), get_material_parameter(m.material, id).dump().c_str());
      }
      if (!several) std::printf("tables needed by the scene (%s layout): %s\n", opt.layout.c_str(), joined(tables_for_components(s.components, opt.compensation, layout)).c_str());
    }
    if (several) {
      std::printf("summary: %zu scene(s), %zu material(s)\n", scenes.size(), summary["materials"].get<std::size_t>());
      std::printf("  components: %s\n", joined(summary["components"].get<std::vector<std::string>>()).c_str());
      std::string f, t;
      for (const auto& [k, v] : summary["features"].items()) f += (f.empty() ? "" : ", ") + k + " (" + v.dump() + ")";
      for (const auto& [k, v] : summary["textured"].items()) t += (t.empty() ? "" : ", ") + k + " (" + v.dump() + ")";
      std::printf("  features:   %s\n", f.empty() ? "(none)" : f.c_str());
      std::printf("  textured:   %s\n", t.empty() ? "(none)" : t.c_str());
      std::printf("  tables (%s layout): %s\n", opt.layout.c_str(),
                  joined(summary["tables"].get<std::vector<std::string>>()).c_str());
      std::printf("  findings:   %zu (material notes)\n", summary["findings"].get<std::size_t>());
    }
  }
  const std::size_t findings = summary["findings"].get<std::size_t>();
  if (opt.strict && findings > 0)
    throw std::runtime_error("--strict: " + std::to_string(findings) +
                             " finding(s) in the materials (unmapped extensions, out-of-range values, approximate mappings)");
}

}  // namespace

void add_scene_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("scene", "glTF scenes: which DSPBR components and tables their materials need");
  cmd->require_subcommand(1);
  auto opt = std::make_shared<AnalyzeOptions>();
  auto* analyze = cmd->add_subcommand("analyze", "Per material: active components, needed tables, textured parameters");
  analyze->add_option("SCENE", opt->paths,
                      ".gltf, .glb or material instance .json files, or folders (their .gltf and .glb files)")
      ->required();
  analyze->add_flag("--json", opt->json,
                    "Print JSON: one scene {\"path\", \"materials\": [{\"name\", \"components\", \"tables\", \"textured\", "
                    "\"notes\"}], \"tables\", \"warnings\", \"findings\"}; several {\"scenes\": [...], \"summary\"}");
  analyze->add_flag("--parameters", opt->parameters, "Also print each material's mapped DSPBR parameters");
  analyze->add_option("--layout", opt->layout,
                      "Name the tables of this layout: renderer (the tables the shader library binds) or published")
      ->check(CLI::IsMember({"renderer", "published"}))
      ->capture_default_str();
  analyze->add_flag("--strict", opt->strict,
                    "Exit 1 when a material has findings: unmapped extensions, values outside DSPBR's ranges, "
                    "approximate mappings (the notes)");
  analyze->add_flag("--transmission-compensation", opt->compensation,
                    "List the tables a renderer with the rough-transmission compensation needs (beyond DSPBR 2025x: "
                    "the Glass tables for volumetric transparent materials)");
  analyze->callback([opt] { run_analyze(*opt); });
}

}  // namespace dspbr::cli
