#include "interrupt_cleanup.h"

#include "commands.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <time.h>

namespace dspbr::cli {

namespace {

// The handler only writes the signal number into a pipe (async-signal-safe); a watcher thread
// reads it and does the cleanup in ordinary code.
int g_pipe_write = -1;
std::atomic<pid_t> g_child{0};  // watch_child

// The signals that end a run with the cleanup: the interrupts and every other signal whose default
// action terminates the process without a core dump that a user or a pipe sends (the fifth fresh
// tester's pass: SIGHUP, SIGUSR1 and SIGPIPE, from `dspbr lut ... | head`, left the staging folder).
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGPIPE};
constexpr std::size_t kSignalCount = sizeof kSignals / sizeof kSignals[0];

// The thread that runs the command (the one that made the InterruptCleanup) keeps writing into
// the staging folder while the watcher removes it: a file it created an instant after the removal
// listed the folder kept the folder (the tenth fresh tester's pass: an interrupted `shader` left
// its staging folder with a complete header in it). Before removing anything the watcher parks it
// in this handler of its own signal, where it waits for the watcher's _exit.
std::atomic<bool> g_parked{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the park handler stores an atomic bool");
extern "C" void on_park(int) {
  g_parked.store(true);
  for (;;) ::pause();
}
int park_signal() { return SIGRTMIN + 1; }

extern "C" void on_signal(int sig) {
  const unsigned char byte = static_cast<unsigned char>(sig);
  if (g_pipe_write >= 0) {
    const ssize_t n = ::write(g_pipe_write, &byte, 1);
    (void)n;  // nothing to do in a handler when the pipe is full
  }
}

// Stops a child started in its own process group (child_process.cpp) and whatever it started: the
// group gets `sig`; the child has up to 2 s to end, then the group gets SIGKILL, and SIGKILL again
// after the child ended, for members that ignore `sig` (the report script's worker processes,
// which held the caller's output pipe and slept forever once their parent was gone). The group's
// id stays reserved while a member lives, so the last kill reaches no other process.
void stop_child_group(pid_t child, int sig) {
  ::kill(-child, sig);
  bool ended = false;
  for (int i = 0; i < 200 && !ended; ++i) {  // 200 x 10 ms
    const pid_t w = ::waitpid(child, nullptr, WNOHANG);
    ended = w == child || (w < 0 && errno == ECHILD);  // ECHILD: the waiting thread reaped it
    if (!ended) {
      const timespec ten_ms{0, 10 * 1000 * 1000};
      ::nanosleep(&ten_ms, nullptr);
    }
  }
  ::kill(-child, SIGKILL);
  if (!ended) ::waitpid(child, nullptr, 0);
}

}  // namespace

struct InterruptCleanup::State {
  std::mutex opening;                 // held while the folder is being created
  std::optional<OutputFolder> out;    // empty until created (or when creating it failed: nothing left)
  int pipe_read = -1, pipe_write = -1;
  pthread_t runner{};                 // the thread that writes the outputs
  struct sigaction old_park {};
  struct sigaction old_actions[kSignalCount] {};
  sigset_t old_mask{};
  std::thread watcher;

  void watch() {
    unsigned char sig = 0;
    ssize_t n;
    while ((n = ::read(pipe_read, &sig, 1)) < 0 && errno == EINTR) {
    }
    if (n != 1 || sig == 0) return;  // closed or told to stop
    if (const pid_t child = g_child.load(); child > 0) stop_child_group(child, sig);  // it may write into the staging folder
    const std::lock_guard<std::mutex> lock(opening);  // wait for a folder being created
    // Parks the runner once no commit is in progress (a commit under way completes first); waits
    // for it up to 2 s (it may be in a system call that ends only then).
    const auto park_runner = [this] {
      if (::pthread_kill(runner, park_signal()) != 0) return;
      for (int i = 0; i < 2000 && !g_parked.load(); ++i) {
        const timespec one_ms{0, 1000 * 1000};
        ::nanosleep(&one_ms, nullptr);
      }
    };
    const std::string what = out ? out->discard(park_runner) : "nothing was written";
    const char* abbrev = sigabbrev_np(sig);
    std::fprintf(stderr, "dspbr: interrupted (SIG%s): %s\n", abbrev ? abbrev : "?", what.c_str());
    std::fflush(stderr);
    ::_exit(128 + sig);
  }
};

InterruptCleanup::InterruptCleanup(const std::string& dir, const std::string& option)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("cannot create a pipe for the interrupt handler");
  ::fcntl(fds[0], F_SETFD, FD_CLOEXEC);
  ::fcntl(fds[1], F_SETFD, FD_CLOEXEC);
  s.pipe_read = fds[0];
  s.pipe_write = g_pipe_write = fds[1];
  s.runner = ::pthread_self();
  struct sigaction park {};
  park.sa_handler = on_park;
  sigemptyset(&park.sa_mask);
  sigaction(park_signal(), &park, &s.old_park);
  s.watcher = std::thread([&s] { s.watch(); });
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigset_t all;
  sigemptyset(&all);
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    sigaction(kSignals[i], &sa, &s.old_actions[i]);
    sigaddset(&all, kSignals[i]);
  }
  sigaddset(&all, park_signal());
  // A signal that arrived before (blocked by the parent, pending) is handled now, before anything
  // is created.
  pthread_sigmask(SIG_UNBLOCK, &all, &s.old_mask);
  try {
    const std::lock_guard<std::mutex> lock(s.opening);
    try {
      s.out.emplace(dir, option);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());  // a folder that cannot be used: exit 2, before any work
    }
  } catch (...) {
    stop();
    throw;
  }
}

void watch_child(pid_t pid) { g_child.store(pid); }

OutputFolder& InterruptCleanup::out() { return *state_->out; }

InterruptCleanup::~InterruptCleanup() { stop(); }

void InterruptCleanup::stop() {
  State& s = *state_;
  if (s.pipe_write < 0) return;
  pthread_sigmask(SIG_SETMASK, &s.old_mask, nullptr);
  for (std::size_t i = 0; i < kSignalCount; ++i) sigaction(kSignals[i], &s.old_actions[i], nullptr);
  const unsigned char stop = 0;
  if (::write(s.pipe_write, &stop, 1) != 1) s.watcher.detach();  // cannot wake it: let it end with the process
  if (s.watcher.joinable()) s.watcher.join();
  sigaction(park_signal(), &s.old_park, nullptr);  // after the watcher: it no longer parks anyone
  g_pipe_write = -1;
  ::close(s.pipe_read);
  ::close(s.pipe_write);
  s.pipe_read = s.pipe_write = -1;
}

}  // namespace dspbr::cli
