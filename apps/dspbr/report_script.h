// The Python report scripts (scripts/report/) run by `dspbr validate` and `dspbr conformance
// check`: found next to the running binary (installed in <prefix>/share/dspbr/report beside
// <prefix>/bin/dspbr; the build copies them into share/dspbr/report of the binary's folder).
#pragma once
#include <string>

namespace dspbr::cli {

// Single-quotes a string for /bin/sh.
std::string shell_quote(const std::string& s);

// The path of scripts/report/<name> next to the running binary; throws std::runtime_error listing
// the places looked at when it is in none.
std::string report_script(const std::string& name);

// Runs `python script folder`; throws std::runtime_error with the command and its exit status when
// it fails ("... (nothing was written to <out>)").
void run_report_script(const std::string& python, const std::string& script, const std::string& folder,
                       const std::string& out);

}  // namespace dspbr::cli
