#include "baseline_libm.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "report_script.h"

namespace dspbr::cli {

const char* const kBaselineLibmTunable = "glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4";

bool wants_baseline_libm(int argc, char** argv) {
#if defined(__x86_64__) && defined(__GLIBC__)
  return argc >= 2 && std::strcmp(argv[1], "fit") == 0;
#else
  (void)argc;  // other platforms have no such tunable (and no committed fits to reproduce)
  (void)argv;
  return false;
#endif
}

bool set_baseline_libm_environment() {
  const char* current = std::getenv("GLIBC_TUNABLES");
  const std::string now = current != nullptr ? current : "";
  const std::string entry = kBaselineLibmTunable;
  if (now.size() >= entry.size() && now.compare(now.size() - entry.size(), entry.size(), entry) == 0) return false;
  const std::string next = now.empty() ? entry : now + ":" + entry;
  return setenv("GLIBC_TUNABLES", next.c_str(), 1) == 0;
}

void run_on_baseline_libm(int argc, char** argv) {
  if (!wants_baseline_libm(argc, argv) || !set_baseline_libm_environment()) return;
  std::string problem;
  try {
    const std::string self = running_executable();
    execv(self.c_str(), argv);
    problem = "cannot re-run " + self + ": " + std::strerror(errno);
  } catch (const std::exception& e) {
    problem = e.what();
  }
  std::fprintf(stderr, "dspbr: warning: %s; the fit runs on this CPU's libm (its last digits may differ from other machines')\n",
               problem.c_str());
}

}  // namespace dspbr::cli
