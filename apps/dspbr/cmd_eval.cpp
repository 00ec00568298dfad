// `dspbr eval`: placeholder until its issue lands.
#include "commands.h"

namespace dspbr::cli {

void add_eval_commands(CLI::App& app) {
  auto* cmd = app.add_subcommand("eval", "(not implemented yet)");
  cmd->callback([] { throw std::runtime_error("'eval' is not implemented yet"); });
}

}  // namespace dspbr::cli
