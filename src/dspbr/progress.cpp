#include "dspbr/progress.h"

#include <unistd.h>

#include <cstdio>

namespace dspbr {

namespace {
// Minimum time between two terminal updates (keeps the cost negligible for fast loops).
constexpr double kPrintInterval = 0.2;  // seconds

std::string format_seconds(double s) {
  char buf[32];
  if (s < 60) std::snprintf(buf, sizeof buf, "%.0fs", s);
  else if (s < 3600) std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
  else std::snprintf(buf, sizeof buf, "%dh%02dm", int(s) / 3600, (int(s) / 60) % 60);
  return buf;
}
}  // namespace

bool Progress::stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, std::size_t total)
    : Progress(std::move(label), total, stderr_is_terminal()) {}

Progress::Progress(std::string label, std::size_t total, bool enabled)
    : label_(std::move(label)), total_(total), enabled_(enabled), live_(enabled && stderr_is_terminal()),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {
  if (live_) print(false);
}

Progress::~Progress() { finish(); }

void Progress::add(std::size_t n) {
  done_.fetch_add(n);
  if (!live_) return;
  const auto now = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_) return;  // another thread is printing: skip this update
  if (std::chrono::duration<double>(now - last_print_).count() < kPrintInterval) return;
  last_print_ = now;
  print(false);
}

void Progress::finish() {
  if (finished_.exchange(true)) return;
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  print(true);
}

void Progress::print(bool final_line) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::size_t d = std::min(done_.load(), total_);
  const double frac = total_ ? double(d) / double(total_) : 1.0;
  std::string tail;
  if (final_line) tail = "in " + format_seconds(elapsed);
  else if (d > 0) tail = "ETA " + format_seconds(elapsed * (1.0 - frac) / frac);
  // \r + clear-to-end-of-line keeps the report on one terminal line.
  std::fprintf(stderr, "%s%s: %zu/%zu (%3.0f%%) %s%s", live_ ? "\r\033[K" : "", label_.c_str(), d, total_, 100.0 * frac,
               tail.c_str(), final_line ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace dspbr
