// dspbr: the DSPBR reference toolchain's command-line tool.
// Exit status: 0 success, 1 checks failed or another failure, 2 bad input or usage (CLI11's
// parse errors included; --help, --help-all and --version exit 0).
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.h"
#include "dspbr/version.h"

namespace {

// Levenshtein distance: insertions, deletions and substitutions of one character.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The error for a word of the command line that stands where a subcommand must be (the app has
// subcommands and no positional arguments) but names none: "unknown subcommand 'lutt'; did you
// mean 'lut'?" when a subcommand is at most 2 edits away, else the list of subcommands.
// "" when every word before the first option names a subcommand.
std::string unknown_subcommand(CLI::App& app, int argc, char** argv) {
  CLI::App* current = &app;
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') return "";  // options (and their values) from here on
    const std::vector<CLI::App*> subs = current->get_subcommands([](CLI::App*) { return true; });
    if (subs.empty() || !current->get_options([](const CLI::Option* o) { return o->get_positional(); }).empty())
      return "";
    const auto named = std::find_if(subs.begin(), subs.end(), [&](CLI::App* s) { return s->check_name(word); });
    if (named != subs.end()) {
      current = *named;
      continue;
    }
    std::string nearest, names;
    std::size_t best = 3;  // suggest only within 2 edits
    for (CLI::App* s : subs) {
      const std::size_t d = edit_distance(word, s->get_name());
      if (d < best) best = d, nearest = s->get_name();
      names += (names.empty() ? "" : ", ") + s->get_name();
    }
    return "unknown subcommand '" + word + "'" +
           (nearest.empty() ? " (choose from " + names + ")" : "; did you mean '" + nearest + "'?");
  }
  return "";
}

}  // namespace

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
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // help, version
    const std::string unknown = unknown_subcommand(app, argc, argv);
    std::fprintf(stderr, "dspbr: error: %s\n", unknown.empty() ? e.what() : unknown.c_str());
    return 2;
  } catch (const dspbr::cli::UsageError& e) {
    std::fprintf(stderr, "dspbr: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dspbr: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
