// Each subcommand of `dspbr` lives in its own cmd_*.cpp and registers itself on the app.
// A command reports bad input by throwing dspbr::cli::UsageError (exit 2) and other failures
// by throwing std::exception (exit 1); main() prints "dspbr: error: <message>".
#pragma once
#include <CLI/CLI.hpp>
#include <stdexcept>

namespace dspbr::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void add_lut_command(CLI::App& app);       // cmd_lut.cpp      (tables)
void add_eval_commands(CLI::App& app);     // cmd_eval.cpp     (eval, sample)
void add_validate_command(CLI::App& app);  // cmd_validate.cpp (validation report)
void add_fit_command(CLI::App& app);       // cmd_fit.cpp      (Ceres fits)
void add_params_command(CLI::App& app);    // cmd_params.cpp   (parameter JSON, instances)
void add_scene_command(CLI::App& app);     // cmd_scene.cpp    (glTF scenes)

}  // namespace dspbr::cli
