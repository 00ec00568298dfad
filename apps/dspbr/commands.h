// Each subcommand of `dspbr` lives in its own cmd_*.cpp and registers itself on the app.
// A command reports bad input by throwing dspbr::cli::UsageError (exit 2) and other failures
// by throwing std::exception (exit 1); main() prints "dspbr: error: <message>".
#pragma once
#include <CLI/CLI.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <cstring>
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "dspbr/io/atomic_file.h"
#include "dspbr/limits.h"
#include "dspbr/io/decimal.h"
#include "dspbr/io/message.h"

namespace dspbr::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// What the command needs is not on this machine (no Vulkan device): exit 77, "skipped".
struct Unavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Checks of integer options, shared by the subcommands (CLI11 validators: a failed check is the
// usage error "--seed: ...", exit status 2).
inline constexpr int kMaxThreads = limits::kThreads;

// An integer option written in decimal digits, from lo to hi (docs/limits.md): CLI11 alone would
// read "010" as octal 8, "0x10" as 16, convert "-1" to an unsigned option as 2^64 - 1 and clamp
// larger numbers. Leading zeros are dropped ("010" is ten) before CLI11 converts the digits.
inline CLI::Validator decimal_integer(unsigned long long lo, unsigned long long hi,
                                     const std::string& meaning = "an integer") {
  return CLI::Validator(
      [lo, hi, meaning](std::string& s) -> std::string {
        const bool digits = !s.empty() && s.size() < 200 && s.find_first_not_of("0123456789") == std::string::npos;
        errno = 0;
        const unsigned long long v = digits ? std::strtoull(s.c_str(), nullptr, 10) : 0;
        if (!digits || errno == ERANGE || v < lo || v > hi) return integer_range_message(meaning, lo, hi, s);
        s = std::to_string(v);
        return "";
      },
      std::to_string(lo) + " to " + std::to_string(hi));
}

// A real-valued option in the one number grammar (src/dspbr/io/decimal.h: decimal as JSON spells
// it): CLI11 alone would take "0x10", "nan" and "inf", and an empty value as the default.
inline CLI::Validator decimal_number() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        const Decimal d = parse_decimal(s);
        if (d.status == Decimal::Ok) return "";
        return "must be a decimal number (as JSON writes numbers: 0.5, -2, 1e-7), got '" + quote_input(s) + "'" +
               (d.status == Decimal::OutOfRange ? " (beyond the range of a double)" : "");
      },
      "NUMBER");
}

// A comma-separated list option (--only, --components, --groups): an empty value is refused (it
// would silently mean the default, "all"), and so is an empty item ("a,", ",a", "a,,b": a stray
// comma), as the vector options refuse them (add_list_option checks each value before splitting).
inline CLI::Validator non_empty_list() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        if (s.empty()) return "must name at least one, got ''";
        if (s.front() == ',' || s.back() == ',' || s.find(",,") != std::string::npos)
          return "has an empty item (a stray comma) in '" + quote_input(s) + "'";
        return "";
      },
      "LIST");
}

// The items of a list value separated by `sep` (a comma, or 'x' in 64x32), spaces dropped; empty
// items are kept for the caller's check (non_empty_list refuses them on the command line).
inline std::vector<std::string> split_list(const std::string& s, char sep = ',') {
  std::vector<std::string> out(1);
  for (char c : s) {
    if (c == sep)
      out.emplace_back();
    else if (c != ' ')
      out.back() += c;
  }
  return out;
}

// A comma-separated list option filling `items` (given more than once, the lists add up); each
// value is checked whole before it is split.
inline CLI::Option* add_list_option(CLI::App* cmd, const std::string& name, std::vector<std::string>& items,
                                    const std::string& description) {
  auto take = [&items](const std::vector<std::string>& values) {
    items.clear();
    for (const std::string& v : values)
      for (std::string& item : split_list(v)) items.push_back(std::move(item));
  };
  return cmd->add_option_function<std::vector<std::string>>(name, take, description)->check(non_empty_list());
}

// An output file option (--out FILE), checked before the work: its folder exists (a command that
// writes one file does not create folders) and the file is not a folder itself.
inline void check_output_file(const std::string& path, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(path);
  const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (path.empty() || !p.has_filename()) throw UsageError(option + ": give a file name, got '" + quote_input(path) + "'");
  if (!fs::is_directory(folder, ec))
    throw UsageError(option + ": the folder '" + quote_input(folder.string()) + "' does not exist (create it first)");
  if (fs::is_directory(p, ec)) throw UsageError(option + ": '" + quote_input(path) + "' is a folder");
  // Can a file be made there? Asked of the filesystem itself, which sees what access() does not
  // (a read-only mount; sysfs, even for root): an unnamed file (O_TMPFILE) leaves nothing behind;
  // where the filesystem has none, a named probe this run creates and removes.
  int probe = ::open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (probe < 0 && (errno == EOPNOTSUPP || errno == EISDIR)) {
    std::string name = (folder / ".dspbr-probe-XXXXXX").string();
    probe = ::mkstemp(name.data());
    if (probe >= 0) ::unlink(name.c_str());
  }
  if (probe >= 0)
    ::close(probe);
  else if (errno == EACCES || errno == EPERM || errno == EROFS || errno == ENOSPC || errno == EDQUOT)
    throw UsageError(option + ": cannot write in the folder '" + quote_input(folder.string()) + "' (" +
                     std::strerror(errno) + ")");
  try {
    require_replaceable(path);
  } catch (const std::runtime_error& e) {
    throw UsageError(option + ": " + e.what());
  }
}

// Seeds: any 64-bit unsigned integer.
inline CLI::Validator non_negative_integer() { return decimal_integer(0, ULLONG_MAX); }

// --threads: 0 (all cores) to kMaxThreads.
inline CLI::Validator thread_count() { return decimal_integer(0, kMaxThreads, "a thread count (0: all cores)"); }

void add_lut_command(CLI::App& app);       // cmd_lut.cpp      (tables)
void add_eval_commands(CLI::App& app);     // cmd_eval.cpp     (eval, sample)
void add_validate_command(CLI::App& app);  // cmd_validate.cpp (validation report)
void add_fit_command(CLI::App& app);       // cmd_fit.cpp      (Ceres fits)
void add_params_command(CLI::App& app);    // cmd_params.cpp   (parameter JSON, instances)
void add_scene_command(CLI::App& app);     // cmd_scene.cpp    (glTF scenes)
void add_conformance_command(CLI::App& app);  // cmd_conformance.cpp (conformance vectors, checker)
void add_shader_command(CLI::App& app);       // cmd_shader.cpp   (shader library specialisation)

}  // namespace dspbr::cli
