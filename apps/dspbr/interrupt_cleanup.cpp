#include "interrupt_cleanup.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace dspbr::cli {

namespace fs = std::filesystem;

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

std::set<fs::path> entries(const fs::path& dir) {
  std::set<fs::path> out;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    out.insert(it->path());
  return out;
}

}  // namespace

struct InterruptCleanup::State {
  fs::path dir;
  bool existed = false;
  std::set<fs::path> before;
  int pipe_read = -1, pipe_write = -1;
  struct sigaction old_int {}, old_term {};
  std::thread watcher;

  // Removes what the run created; returns the message's "removed ..." part.
  std::string clean() const {
    std::error_code ec;
    if (!existed) {
      const bool was_there = fs::exists(dir, ec);
      fs::remove_all(dir, ec);
      return was_there ? "removed the output folder '" + dir.string() + "' it created"
                       : "nothing was written yet";
    }
    std::vector<fs::path> created;
    for (const fs::path& p : entries(dir))
      if (!before.count(p)) created.push_back(p);
    std::size_t removed = 0;
    for (const fs::path& p : created) {
      if (!fs::exists(fs::symlink_status(p, ec))) continue;  // inside a folder removed already
      fs::remove_all(p, ec);
      if (!ec) ++removed;
    }
    return "removed " + std::to_string(removed) + " file(s) or folder(s) it created in '" + dir.string() +
           "' (what was there before is kept)";
  }

  void watch() {
    unsigned char sig = 0;
    ssize_t n;
    while ((n = ::read(pipe_read, &sig, 1)) < 0 && errno == EINTR) {
    }
    if (n != 1 || sig == 0) return;  // closed or told to stop
    const std::string what = clean();
    clean();  // again: a file renamed into place while the first pass ran
    std::fprintf(stderr, "dspbr: interrupted (%s): %s\n", sig == SIGINT ? "SIGINT" : "SIGTERM", what.c_str());
    std::fflush(stderr);
    ::_exit(128 + sig);
  }
};

InterruptCleanup::InterruptCleanup(const std::string& dir) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.dir = fs::path(dir);
  std::error_code ec;
  s.existed = fs::exists(s.dir, ec);
  if (s.existed) s.before = entries(s.dir);
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
