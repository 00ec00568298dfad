#include "interrupt_cleanup.h"

#include "commands.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace dspbr::cli {

namespace {

// The handler only writes the signal number into a pipe (async-signal-safe); a watcher thread
// reads it and does the cleanup in ordinary code.
int g_pipe_write = -1;

extern "C" void on_signal(int sig) {
  const unsigned char byte = static_cast<unsigned char>(sig);
  if (g_pipe_write >= 0) {
    const ssize_t n = ::write(g_pipe_write, &byte, 1);
    (void)n;  // nothing to do in a handler when the pipe is full
  }
}

}  // namespace

OutputFolder open_output_folder(const std::string& dir, const std::string& option) {
  try {
    return OutputFolder(dir, option);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

struct InterruptCleanup::State {
  OutputFolder* out = nullptr;
  int pipe_read = -1, pipe_write = -1;
  struct sigaction old_int {}, old_term {};
  std::thread watcher;

  void watch() {
    unsigned char sig = 0;
    ssize_t n;
    while ((n = ::read(pipe_read, &sig, 1)) < 0 && errno == EINTR) {
    }
    if (n != 1 || sig == 0) return;  // closed or told to stop
    const std::string what = out->discard();
    std::fprintf(stderr, "dspbr: interrupted (%s): %s\n", sig == SIGINT ? "SIGINT" : "SIGTERM", what.c_str());
    std::fflush(stderr);
    ::_exit(128 + sig);
  }
};

InterruptCleanup::InterruptCleanup(OutputFolder& out) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.out = &out;
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("cannot create a pipe for the interrupt handler");
  ::fcntl(fds[0], F_SETFD, FD_CLOEXEC);
  ::fcntl(fds[1], F_SETFD, FD_CLOEXEC);
  s.pipe_read = fds[0];
  s.pipe_write = g_pipe_write = fds[1];
  s.watcher = std::thread([&s] { s.watch(); });
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, &s.old_int);
  sigaction(SIGTERM, &sa, &s.old_term);
}

InterruptCleanup::~InterruptCleanup() {
  State& s = *state_;
  sigaction(SIGINT, &s.old_int, nullptr);
  sigaction(SIGTERM, &s.old_term, nullptr);
  const unsigned char stop = 0;
  if (::write(s.pipe_write, &stop, 1) != 1) s.watcher.detach();  // cannot wake it: let it end with the process
  if (s.watcher.joinable()) s.watcher.join();
  g_pipe_write = -1;
  ::close(s.pipe_read);
  ::close(s.pipe_write);
}

}  // namespace dspbr::cli
