// Each subcommand of `dspbr` lives in its own cmd_*.cpp and registers itself on the app.
// A command reports bad input by throwing dspbr::cli::UsageError (exit 2) and other failures
// by throwing std::exception (exit 1); main() prints "dspbr: error: <message>".
#pragma once
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "dspbr/limits.h"

namespace dspbr::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Checks of integer options, shared by the subcommands (CLI11 validators: a failed check is the
// usage error "--seed: ...", exit status 2).
inline constexpr int kMaxThreads = limits::kThreads;

// Digits only, below 2^64: CLI11 would convert "-1" to an unsigned option as 2^64 - 1 and clamp
// larger numbers to it.
inline CLI::Validator non_negative_integer() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        const bool digits = !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
        errno = 0;
        if (!digits || (std::strtoull(s.c_str(), nullptr, 10) == ULLONG_MAX && errno == ERANGE))
          return "must be a non-negative integer below 2^64, got '" + s + "'";
        return "";
      },
      ">= 0");
}

// --threads: 0 (all cores) to kMaxThreads.
inline CLI::Validator thread_count() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        const std::string v = s.substr(std::min(s.find_first_not_of('0'), s.size()));  // no leading zeros
        if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || v.size() > 4 ||
            (!v.empty() && std::stoi(v) > kMaxThreads))
          return "must be a thread count from 0 (all cores) to " + std::to_string(kMaxThreads) + ", got '" + s + "'";
        return "";
      },
      "0 to " + std::to_string(kMaxThreads));
}

void add_lut_command(CLI::App& app);       // cmd_lut.cpp      (tables)
void add_eval_commands(CLI::App& app);     // cmd_eval.cpp     (eval, sample)
void add_validate_command(CLI::App& app);  // cmd_validate.cpp (validation report)
void add_fit_command(CLI::App& app);       // cmd_fit.cpp      (Ceres fits)
void add_params_command(CLI::App& app);    // cmd_params.cpp   (parameter JSON, instances)
void add_scene_command(CLI::App& app);     // cmd_scene.cpp    (glTF scenes)

}  // namespace dspbr::cli
