#include "report_script.h"

#include "child_process.h"
#include "commands.h"

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

std::string report_script(const std::string& name) {
  return shared_path("report/" + name, "; --no-html writes only the data");
}

void run_report_script(const std::string& python, const std::string& script, const std::string& folder,
                       const std::string& out) {
  const std::string cmd = shell_quote(python) + " " + shell_quote(script) + " " + shell_quote(folder);
  const ChildExit r = run_child({python, script, folder});
  if (!r.started)
    throw UsageError("--python: cannot run " + shell_quote(python) + ": " + std::strerror(r.error) +
                     " (nothing was written to " + out + ")");
  if (r.status != 0)
    throw std::runtime_error("the report script failed (exit status " + std::to_string(r.status) + "): " + cmd +
                             " (nothing was written to " + out + ")");
}

}  // namespace dspbr::cli
