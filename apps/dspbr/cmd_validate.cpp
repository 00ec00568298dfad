// `dspbr validate`: placeholder until its issue lands.
#include "commands.h"

namespace dspbr::cli {

void add_validate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("validate", "(not implemented yet)");
  cmd->callback([] { throw std::runtime_error("'validate' is not implemented yet"); });
}

}  // namespace dspbr::cli
