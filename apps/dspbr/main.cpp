// dspbr: the DSPBR reference toolchain's command-line tool.
#include <cstdio>
#include <exception>

#include "commands.h"
#include "dspbr/version.h"

int main(int argc, char** argv) {
  CLI::App app{"dspbr: reference toolchain for the Enterprise PBR Shading Model (DSPBR 2025x)"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Print help for every subcommand");
  app.set_version_flag("--version", std::string("dspbr ") + dspbr::version_string(),
                       "Print the version (project version and git describe of the build) and exit");
  dspbr::cli::add_lut_command(app);
  dspbr::cli::add_eval_commands(app);
  dspbr::cli::add_validate_command(app);
  dspbr::cli::add_fit_command(app);
  dspbr::cli::add_params_command(app);
  dspbr::cli::add_scene_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const dspbr::cli::UsageError& e) {
    std::fprintf(stderr, "dspbr: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dspbr: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
