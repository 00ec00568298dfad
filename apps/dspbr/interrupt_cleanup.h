// An interrupted run removes what it created and says so: while an InterruptCleanup lives,
// SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM and SIGPIPE discard the run's
// OutputFolder (io/output_folder.h: its staging folder and the folders it created, nothing else),
// print "dspbr: interrupted (SIGINT): <what was removed>" on stderr and exit with status 128 + the
// signal number (130 for SIGINT, 143 for SIGTERM). An interrupt while the outputs are being moved
// into place waits until they all are. (SIGKILL cannot be caught: docs/limits.md.)
#pragma once
#include <sys/types.h>

#include <memory>
#include <string>

#include "dspbr/io/output_folder.h"

namespace dspbr::cli {

// Installs the handlers first, then opens the run's output folder for `option`
// (io/output_folder.h; a folder that cannot be used is a UsageError, exit 2, before any work): an interrupt
// at any moment, even while the folder and its staging folder are being created, leaves nothing
// behind and exits 128 + signal with one line.
class InterruptCleanup {
 public:
  explicit InterruptCleanup(const std::string& dir, const std::string& option = "--out");
  ~InterruptCleanup();  // restores the previous handlers; then the folder discards unless committed
  OutputFolder& out();
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;

 private:
  void stop();  // restores the handlers, ends the watcher
  struct State;
  std::unique_ptr<State> state_;
};

// The child process a command is waiting for (child_process.h, which starts it as the leader of
// its own process group), 0 for none: an interrupt sends its group the same signal, SIGKILL
// after 2 s and once it ended, and waits for it before the cleanup.
void watch_child(pid_t pid);

}  // namespace dspbr::cli
