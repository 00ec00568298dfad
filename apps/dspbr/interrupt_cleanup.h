// An interrupted run removes what it created and says so: while an InterruptCleanup lives,
// SIGINT and SIGTERM make the command remove the output folder when the run created it, else
// every file and folder the run created inside it (temporary files included; files that existed
// before are kept, complete since outputs are renamed into place, io/atomic_file.h), print
// "dspbr: interrupted (SIGINT): removed ..." on stderr and exit with status 128 + the signal
// number (130 for SIGINT, 143 for SIGTERM).
#pragma once
#include <memory>
#include <string>

namespace dspbr::cli {

class InterruptCleanup {
 public:
  // Records what `dir` holds now (nothing when it does not exist yet) and installs the handlers.
  explicit InterruptCleanup(const std::string& dir);
  ~InterruptCleanup();  // restores the previous handlers
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace dspbr::cli
