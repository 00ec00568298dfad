// `dspbr shader (--scene SCENE | --components LIST) --out DIR`: the shader library specialised for
// a scene's materials (docs/renderer.md, "Only what a scene needs"): DIR/dspbr_specialization.h,
// and the lookup textures to bind printed.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include "commands.h"
#include "interrupt_cleanup.h"
#include "dspbr/component.h"
#include "dspbr/io/atomic_file.h"
#include "dspbr/nearest_name.h"
#include "dspbr/scene/scene_analysis.h"
#include "dspbr/scene/shader_specialization.h"

namespace dspbr::cli {

namespace {

struct ShaderArgs {
  std::string scene, components, out;
};

// A comma-separated list of component names (shader_components()); an unknown one is a usage error
// with the nearest name.
uint32_t parse_components(const std::string& list) {
  std::vector<std::string> names;
  for (uint32_t c : shader_components()) names.push_back(component_name(Component(c)));
  uint32_t mask = 0;
  std::stringstream in(list);
  for (std::string word; std::getline(in, word, ',');) {
    bool found = false;
    for (uint32_t c : shader_components())
      if (word == component_name(Component(c))) mask |= c, found = true;
    if (found) continue;
    const std::string near = nearest_name(word, names);
    std::string all;
    for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
    throw UsageError("--components: unknown component '" + word + "'" +
                     (near.empty() ? " (components: " + all + ")" : "; did you mean '" + near + "'?"));
  }
  return mask;
}

void run(const ShaderArgs& a) {
  uint32_t mask = 0;
  std::string source;
  if (!a.scene.empty()) {
    SceneAnalysis s;
    try {
      s = analyze_scene(a.scene);
    } catch (const std::runtime_error& e) {
      throw UsageError(e.what());
    }
    mask = s.components;
    source = "the materials of " + std::filesystem::path(a.scene).filename().string();
  } else {
    mask = parse_components(a.components);
    source = "the components " + a.components;
  }
  InterruptCleanup run_out(a.out);  // the handlers first, then the output folder
  OutputFolder& out = run_out.out();
  write_text_atomically((std::filesystem::path(out.staging()) / "dspbr_specialization.h").string(),
                        shader_specialization_header(mask, source));
  out.commit();
  std::string kept;
  for (uint32_t c : shader_components())
    if (mask & c) kept += (kept.empty() ? "" : ", ") + std::string(component_name(Component(c)));
  std::printf("components: %s\n", kept.empty() ? "(none)" : kept.c_str());
  std::printf("textures to bind:");
  const std::vector<ShaderTexture> tex = shader_textures(mask);
  if (tex.empty()) std::printf(" none");
  for (const ShaderTexture& t : tex) std::printf(" %s (%d)", t.table.c_str(), t.index);
  std::printf("\nwrote %s/dspbr_specialization.h\n", a.out.c_str());
}

}  // namespace

void add_shader_command(CLI::App& app) {
  auto args = std::make_shared<ShaderArgs>();
  auto* cmd = app.add_subcommand("shader", "The shader library specialised for a scene: only the lobes and tables "
                                           "its materials use (docs/renderer.md)");
  auto* scene = cmd->add_option("--scene", args->scene, "A .gltf, .glb or material instance .json whose materials it serves");
  auto* comps = cmd->add_option("--components", args->components,
                                "Comma-separated components instead of a scene (metallic, opaque_dielectric, "
                                "thin_transparent, volumetric_transparent, translucency, thin_film, sheen, flakes, "
                                "clearcoat, emission, dispersion)")
                   ->check(non_empty_list());
  scene->excludes(comps);
  comps->excludes(scene);
  cmd->add_option("--out", args->out, "Output folder for dspbr_specialization.h")->required();
  cmd->callback([args] {
    if (args->scene.empty() && args->components.empty()) throw UsageError("shader: give --scene FILE or --components LIST");
    run(*args);
  });
}

}  // namespace dspbr::cli
