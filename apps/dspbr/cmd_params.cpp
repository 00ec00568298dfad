// `dspbr params`: placeholder until its issue lands.
#include "commands.h"

namespace dspbr::cli {

void add_params_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("params", "(not implemented yet)");
  cmd->callback([] { throw std::runtime_error("'params' is not implemented yet"); });
}

}  // namespace dspbr::cli
