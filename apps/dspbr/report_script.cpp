#include "report_script.h"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace dspbr::cli {

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string report_script(const std::string& name) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot locate the dspbr executable (/proc/self/exe): " + ec.message());
  std::string tried;
  for (const fs::path& dir : {exe.parent_path().parent_path() / "share/dspbr/report",
                              exe.parent_path() / "share/dspbr/report"}) {
    const fs::path script = dir / name;
    if (fs::is_regular_file(script, ec)) return script.string();
    tried += (tried.empty() ? "" : ", ") + script.string();
  }
  throw std::runtime_error("report script not found (looked for " + tried + "); --no-html writes only the data");
}

void run_report_script(const std::string& python, const std::string& script, const std::string& folder,
                       const std::string& out) {
  const std::string cmd = shell_quote(python) + " " + shell_quote(script) + " " + shell_quote(folder);
  const int st = std::system(cmd.c_str());
  const int rc = (st != -1 && WIFEXITED(st)) ? WEXITSTATUS(st) : -1;
  if (rc != 0)
    throw std::runtime_error("the report script failed (exit status " + std::to_string(rc) + "): " + cmd +
                             " (nothing was written to " + out + ")");
}

}  // namespace dspbr::cli
