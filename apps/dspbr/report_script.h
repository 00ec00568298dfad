// Files the commands find next to the running binary: the Python report scripts (scripts/report/)
// run by `dspbr validate` and `dspbr conformance check` (installed in <prefix>/share/dspbr/report
// beside <prefix>/bin/dspbr; the build copies them into share/dspbr/report of the binary's folder),
// and the validation scenes (share/dspbr/scenes) of `dspbr conformance generate`.
#pragma once
#include <string>
#include <vector>

#include "dspbr/io/output_folder.h"

namespace dspbr::cli {

// The path of the running binary (/proc/self/exe); throws std::runtime_error when it cannot be read.
std::string running_executable();

// Single-quotes a string for /bin/sh.
std::string shell_quote(const std::string& s);

// The path of share/dspbr/<relative> next to the running binary (<prefix>/share/dspbr beside
// <prefix>/bin, or share/dspbr in the binary's folder, where the build copies the report scripts and
// the validation scenes); throws std::runtime_error listing the places looked at when it is in none.
std::string shared_path(const std::string& relative, const std::string& hint);

// shared_path("report/<name>"): scripts/report/<name>, once check_report_python(python) passed.
std::string report_script(const std::string& name, const std::string& python);

// Runs `python script folder` (without a $HOME folder, with MPLCONFIGDIR in folder/.matplotlib,
// removed after it); throws std::runtime_error with the command and its exit status when
// it fails, or when it wrote no folder/index.html ("... (nothing was written to <out>)").
void run_report_script(const std::string& python, const std::string& script, const std::string& folder,
                       const std::string& out);

// Before any work: python imports numpy and jinja2 and finds matplotlib (not imported: that would
// write its caches under $HOME), else UsageError naming --python and what to install (about 0.3 s).
void check_report_python(const std::string& python);

// A run without HTML (--no-html) into a folder that holds an earlier run's pages: each of `pages`
// (index.html, ...) that exists there is replaced, in the new set, by a page that says this run
// wrote only `data` (relative path) with `verdict`, so the folder never shows an earlier run's
// verdict beside this run's data. The earlier plots stay (nothing of an earlier run is deleted),
// no longer referenced.
void replace_earlier_pages(const OutputFolder& out, const std::vector<std::string>& pages, const std::string& data,
                           const std::string& verdict);

}  // namespace dspbr::cli
