// `dspbr fit`: placeholder until its issue lands.
#include "commands.h"

namespace dspbr::cli {

void add_fit_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("fit", "(not implemented yet)");
  cmd->callback([] { throw std::runtime_error("'fit' is not implemented yet"); });
}

}  // namespace dspbr::cli
