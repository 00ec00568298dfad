#include "report_script.h"

#include "dspbr/io/atomic_file.h"

#include "child_process.h"
#include "commands.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace dspbr::cli {

std::string running_executable() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot locate the dspbr executable (/proc/self/exe): " + ec.message());
  return exe.string();
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string shared_path(const std::string& relative, const std::string& hint) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = running_executable();
  std::string tried;
  for (const fs::path& dir : {exe.parent_path().parent_path() / "share/dspbr", exe.parent_path() / "share/dspbr"}) {
    const fs::path p = dir / relative;
    if (fs::exists(p, ec)) return p.string();
    tried += (tried.empty() ? "" : ", ") + p.string();
  }
  throw std::runtime_error(relative + " not found (looked for " + tried + ")" + hint);
}

std::string report_script(const std::string& name, const std::string& python) {
  std::string script = shared_path("report/" + name, "; --no-html writes only the data");
  check_report_python(python);
  return script;
}

void run_report_script(const std::string& python, const std::string& script, const std::string& folder,
                       const std::string& out) {
  // Messages name the command without the staging folder it was given (a temporary path).
  const std::string cmd = shell_quote(python) + " " + shell_quote(script);
  // matplotlib keeps its caches under $HOME, and creates a missing $HOME: without one, the script
  // gets a folder of the run's own staging folder instead, removed before the commit.
  const std::filesystem::path mpl = std::filesystem::path(folder) / ".matplotlib";
  std::error_code ec;
  const char* home = std::getenv("HOME");
  const bool own_config = home == nullptr || !std::filesystem::is_directory(home, ec);
  if (own_config) std::filesystem::create_directory(mpl, ec);
  const ChildExit r = run_child({python, script, folder}, "", own_config ? std::vector<std::string>{"MPLCONFIGDIR=" + mpl.string()}
                                                                          : std::vector<std::string>{});
  if (own_config) std::filesystem::remove_all(mpl, ec);
  if (!r.started)
    throw UsageError("--python: cannot run " + shell_quote(python) + ": " + std::strerror(r.error) +
                     " (nothing was written to " + out + ")");
  if (r.status != 0)
    throw std::runtime_error("the report script failed (exit status " + std::to_string(r.status) + "): " + cmd +
                             " (nothing was written to " + out + ")");
  if (!std::filesystem::is_regular_file(std::filesystem::path(folder) / "index.html", ec))
    throw std::runtime_error("the report script exited 0 without writing index.html: " + cmd +
                             " (nothing was written to " + out + ")");
}

void check_report_python(const std::string& python) {
  // matplotlib found, not imported: importing it writes its caches under $HOME (docs/limits.md).
  const ChildExit r = run_child(
      {python, "-c", "import importlib.util, numpy, jinja2\nif importlib.util.find_spec('matplotlib') is None: raise SystemExit(1)"},
      "/dev/null");
  if (!r.started) throw UsageError("--python: cannot run " + shell_quote(python) + ": " + std::strerror(r.error));
  if (r.status != 0)
    throw UsageError("--python: " + shell_quote(python) + " cannot import numpy, matplotlib and jinja2 (exit status " +
                     std::to_string(r.status) +
                     "): give a Python that can (Debian: python3-numpy python3-matplotlib python3-jinja2), or --no-html");
}

void replace_earlier_pages(const OutputFolder& out, const std::vector<std::string>& pages, const std::string& data,
                           const std::string& verdict) {
  for (const std::string& page : pages) {
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::path(out.dir()) / page, ec)) continue;
    const std::string html =
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>dspbr report: " + verdict +
        "</title></head>\n<body><p>The last run into this folder wrote no HTML (<code>--no-html</code>): its verdict is <b>" +
        verdict + "</b>, its data <a href=\"" + data + "\">" + data +
        "</a>. The plots beside this page are an earlier run's and do not describe it.</p></body></html>\n";
    write_text_file(out.staging() + "/" + page, html, out.dir() + "/" + page);
  }
}

}  // namespace dspbr::cli
