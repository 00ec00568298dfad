// `dspbr lut`: placeholder until its issue lands.
#include "commands.h"

namespace dspbr::cli {

void add_lut_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("lut", "(not implemented yet)");
  cmd->callback([] { throw std::runtime_error("'lut' is not implemented yet"); });
}

}  // namespace dspbr::cli
