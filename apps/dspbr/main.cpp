// dspbr: the DSPBR reference toolchain's command-line tool.
// Exit status: 0 success, 1 checks failed or another failure, 2 bad input or usage (CLI11's
// parse errors included; --help, --help-all and --version exit 0).
//
// Built twice (CMakeLists.txt): `dspbr-full` has every subcommand; `dspbr` (DSPBR_FRONT) has
// --version, eval, sample, params and scene, links none of OpenImageIO, Ceres and their ~270
// shared libraries (loading them took ~0.4 s before any command ran), and runs dspbr-full from its
// own folder, with the same arguments, for everything else (lut, validate, fit, conformance, --help).
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "baseline_libm.h"
#include "commands.h"
#include "report_script.h"
#include "dspbr/io/atomic_file.h"
#include "dspbr/io/message.h"
#include "dspbr/nearest_name.h"
#include "dspbr/version.h"

namespace {

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
    std::vector<std::string> candidates;
    std::string names;
    for (CLI::App* s : subs) {
      candidates.push_back(s->get_name());
      names += (names.empty() ? "" : ", ") + s->get_name();
    }
    const std::string nearest = dspbr::nearest_name(word, candidates);  // within 2 edits
    return "unknown subcommand '" + word + "'" +
           (nearest.empty() ? " (choose from " + names + ")" : "; did you mean '" + nearest + "'?");
  }
  return "";
}

// The error for an option of the command line ("--veiw") that the (sub)command it follows does
// not have: "unknown option '--veiw' of 'eval'; did you mean '--view'?" (within 2 edits). Found
// before CLI11's own message, which may be about a required option instead. "" when every
// option is known.
std::string unknown_option(CLI::App& app, int argc, char** argv) {
  CLI::App* current = &app;
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--") return "";  // positionals from here on
    if (word.rfind("--", 0) != 0) {
      const std::vector<CLI::App*> subs = current->get_subcommands([](CLI::App*) { return true; });
      const auto named = std::find_if(subs.begin(), subs.end(), [&](CLI::App* s) { return s->check_name(word); });
      if (named != subs.end()) current = *named;
      continue;  // a value or a positional
    }
    const std::string name = word.substr(0, word.find('='));
    bool known = false;
    std::vector<std::string> names;
    for (CLI::App* a = current; a != nullptr; a = a->get_parent())
      for (const CLI::Option* o : a->get_options([](const CLI::Option*) { return true; }))
        for (const std::string& l : o->get_lnames()) {
          names.push_back("--" + l);
          known = known || name == "--" + l;
        }
    if (known) continue;
    const std::string nearest = dspbr::nearest_name(name, names);
    return "unknown option '" + name + "'" + (current == &app ? "" : " of '" + current->get_name() + "'") +
           (nearest.empty() ? " (--help lists the options)" : "; did you mean '" + nearest + "'?");
  }
  return "";
}

#ifdef DSPBR_FRONT
// True when the front binary runs this command line itself: a first word among its subcommands,
// or --version alone.
bool front_runs(int argc, char** argv) {
  if (argc < 2) return false;
  const std::string first = argv[1];
  if (first == "--version") return argc == 2;
  for (const char* name : {"eval", "sample", "params", "scene"})
    if (first == name) return true;
  return false;
}

// Replaces the process by dspbr-full of the running binary's folder with the same arguments;
// returns only on failure (exit status 1, the reason on stderr).
int run_full(char** argv) {
  std::string full;
  try {
    const std::string self = dspbr::cli::running_executable();
    full = self.substr(0, self.rfind('/') + 1) + "dspbr-full";
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dspbr: error: %s\n", dspbr::one_line(e.what()).c_str());
    return 1;
  }
  execv(full.c_str(), argv);
  std::fprintf(stderr, "dspbr: error: cannot run %s: %s\n", full.c_str(), std::strerror(errno));
  return 1;
}
#endif

// 0 when everything printed on stdout reached it; else 1 with the reason on stderr (a full disk, a
// closed stdout: the result would be lost while the exit status says success).
int standard_output_written() {
  if (std::cout.good()) errno = 0;  // else it holds the reason of the write that failed (help, version)
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  if (std::cout.good() && flushed && !std::ferror(stdout)) return 0;
  // errno holds the reason when the last write failed; a write that failed earlier (a command's own
  // fflush) left only the stream's error flag, and no reason is made up for it.
  if (errno)
    std::fprintf(stderr, "dspbr: error: cannot write the output to stdout: %s\n", std::strerror(errno));
  else
    std::fprintf(stderr, "dspbr: error: cannot write the output to stdout (a write failed; the output is incomplete)\n");
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef DSPBR_FRONT
  if (!front_runs(argc, argv)) {
    if (dspbr::cli::wants_baseline_libm(argc, argv)) dspbr::cli::set_baseline_libm_environment();
    return run_full(argv);
  }
#else
  dspbr::cli::run_on_baseline_libm(argc, argv);
#endif
  CLI::App app{"dspbr: reference toolchain for the Enterprise PBR Shading Model (DSPBR 2025x)"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Print help for every subcommand");
  app.set_version_flag("--version", std::string("dspbr ") + dspbr::version_string(),
                       "Print the version (project version and git describe of the build) and exit");
#ifndef DSPBR_FRONT
  dspbr::cli::add_lut_command(app);
#endif
  dspbr::cli::add_eval_commands(app);
#ifndef DSPBR_FRONT
  dspbr::cli::add_validate_command(app);
  dspbr::cli::add_fit_command(app);
#endif
  dspbr::cli::add_params_command(app);
  dspbr::cli::add_scene_command(app);
#ifndef DSPBR_FRONT
  dspbr::cli::add_conformance_command(app);
  dspbr::cli::add_shader_command(app);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {  // help, version
      errno = 0;
      app.exit(e);
      return standard_output_written();
    }
    std::string unknown = unknown_subcommand(app, argc, argv);
    if (unknown.empty()) unknown = unknown_option(app, argc, argv);
    std::fprintf(stderr, "dspbr: error: %s\n", dspbr::one_line(unknown.empty() ? e.what() : unknown).c_str());
    return 2;
  } catch (const dspbr::cli::UsageError& e) {
    std::fprintf(stderr, "dspbr: error: %s\n", dspbr::one_line(e.what()).c_str());
    return 2;
  } catch (const dspbr::NotReplaceable& e) {  // an output path taken by a folder, FIFO, ...: bad input
    std::fprintf(stderr, "dspbr: error: %s\n", dspbr::one_line(e.what()).c_str());
    return 2;
  } catch (const dspbr::cli::Unavailable& e) {
    std::fprintf(stderr, "dspbr: %s\n", dspbr::one_line(e.what()).c_str());
    return 77;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "dspbr: error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dspbr: error: %s\n", dspbr::one_line(e.what()).c_str());
    return 1;
  }
  return standard_output_written();
}
