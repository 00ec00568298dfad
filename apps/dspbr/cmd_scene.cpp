// `dspbr scene`: placeholder until its issue lands.
#include "commands.h"

namespace dspbr::cli {

void add_scene_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("scene", "(not implemented yet)");
  cmd->callback([] { throw std::runtime_error("'scene' is not implemented yet"); });
}

}  // namespace dspbr::cli
