// A small progress reporter for long runs: "label: done/total (pct) ETA 12s" on one
// terminal line while it runs, when stderr is a terminal (isatty); when it is not (a log, a
// pipe), one plain line "label: total/total (100%) in 3s" at the end, so a log shows what ran.
// Thread-safe: any thread may call add(); output is rate-limited to a few updates per second.
#pragma once
#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace dspbr {

class Progress {
 public:
  // `enabled` defaults to "stderr is a terminal"; pass false to force silence, true for the live
  // line on a terminal and the final plain line elsewhere.
  Progress(std::string label, std::size_t total);
  Progress(std::string label, std::size_t total, bool enabled);
  ~Progress();  // calls finish()
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Records n more finished items (thread-safe).
  void add(std::size_t n = 1);
  // Prints the final line (with the elapsed time) and a newline; later calls do nothing.
  void finish();

  std::size_t done() const { return done_.load(); }
  std::size_t total() const { return total_; }
  bool enabled() const { return enabled_; }

  // True when stderr is a terminal.
  static bool stderr_is_terminal();

 private:
  void print(bool final_line);

  std::string label_;
  std::size_t total_;
  bool enabled_, live_;
  std::atomic<std::size_t> done_{0};
  std::atomic<bool> finished_{false};
  std::chrono::steady_clock::time_point start_, last_print_;
  std::mutex mutex_;
};

}  // namespace dspbr
