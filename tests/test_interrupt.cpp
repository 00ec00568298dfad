// An interrupted `dspbr lut` removes what it created and says so (apps/dspbr/interrupt_cleanup.h):
// the tool is started on a long run, interrupted once its handlers are installed, and the output
// folder is compared with what was there before.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

// A run far longer than the test: a 2048x2048 GGX_E table at the full fixed budget.
const std::vector<std::string> kLongRun = {"lut", "--tables", "GGX_E", "--size", "GGX_E=2048x2048", "--target-error",
                                           "0", "--formats", "json", "--threads", "1"};

struct LutRun {
  pid_t pid = -1;
  std::string log;
};

// `pending`: a signal raised in the child while blocked, so that it is pending from the first
// instruction of the tool on (the earliest possible interrupt).
LutRun start_args(std::vector<std::string> args, const std::string& log, int pending = 0);

LutRun start(const std::string& out, const std::string& log, int pending = 0) {
  std::vector<std::string> args = {DSPBR_EXE};
  args.insert(args.end(), kLongRun.begin(), kLongRun.end());
  args.push_back("--out");
  args.push_back(out);
  return start_args(args, log, pending);
}

// Runs `args` (args[0] the program) with stderr into `log`.
LutRun start_args(std::vector<std::string> args, const std::string& log, int pending) {
  LutRun r;
  r.log = log;
  r.pid = fork();
  if (r.pid == 0) {
    FILE* f = std::fopen(log.c_str(), "w");
    if (f) dup2(fileno(f), 2);
    if (pending != 0) {
      sigset_t set;
      sigemptyset(&set);
      sigaddset(&set, pending);
      sigprocmask(SIG_BLOCK, &set, nullptr);
      raise(pending);
    }
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return r;
}

// Whether the process catches `sig` (bit sig - 1 of SigCgt in /proc/PID/status): the tool has
// installed its handlers.
bool catches(pid_t pid, int sig) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("SigCgt:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (sig - 1)) & 1;
  return false;
}

// Waits (polling, up to a minute: the condition, not the time, is what is tested) for `ready`.
template <class F>
bool wait_for(F ready) {
  for (int i = 0; i < 6000; ++i) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// Interrupts the run with `sig` once it catches it and its output folder exists; returns the
// exit status (-1 when it did not exit normally).
int interrupt(const LutRun& r, const fs::path& out, int sig) {
  EXPECT_TRUE(wait_for([&] { return catches(r.pid, sig) && fs::exists(out); })) << read_all(r.log);
  kill(r.pid, sig);
  int status = 0;
  waitpid(r.pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

// SIGHUP, SIGUSR1 and SIGPIPE too (the fifth fresh tester's pass: each left the staging folder).
TEST(Interrupt, LutRemovesTheFolderItCreated) {
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGUSR1, SIGPIPE}) {
    const fs::path out = fs::path(::testing::TempDir()) / ("interrupt_new_" + std::to_string(sig));
    fs::remove_all(out);
    const LutRun r = start(out.string(), out.string() + ".log");
    const int status = interrupt(r, out, sig);
    EXPECT_EQ(status, 128 + sig) << read_all(r.log);
    EXPECT_FALSE(fs::exists(out)) << "left behind: " << out;
    const std::string log = read_all(r.log);
    EXPECT_NE(log.find(std::string("dspbr: interrupted (SIG") + sigabbrev_np(sig) +
                       "): nothing was written; removed the 1 folder(s) it created ('" + out.string() + "')"),
              std::string::npos)
        << log;
  }
}

TEST(Interrupt, LutKeepsWhatWasThereBefore) {
  const fs::path out = fs::path(::testing::TempDir()) / "interrupt_existing";
  fs::remove_all(out);
  fs::create_directories(out / "sub");
  std::ofstream(out / "keep.txt") << "kept";
  std::ofstream(out / "sub" / "dspbr_luts.json") << "an older file";
  const std::set<std::string> before = listing(out);
  const LutRun r = start(out.string(), out.string() + ".log");
  // Files another program writes into the folder while the run works are not the run's either,
  // including one at the name of an output (the run once removed every file that appeared).
  std::set<std::string> expected = before;
  EXPECT_TRUE(wait_for([&] { return catches(r.pid, SIGINT); })) << read_all(r.log);
  std::ofstream(out / "written_meanwhile.txt") << "someone else's";
  std::ofstream(out / "dspbr_luts.json") << "someone else's table";
  expected.insert({"written_meanwhile.txt", "dspbr_luts.json"});
  const int status = interrupt(r, out, SIGINT);
  EXPECT_EQ(status, 128 + SIGINT) << read_all(r.log);
  EXPECT_EQ(listing(out), expected);
  EXPECT_EQ(read_all((out / "dspbr_luts.json").string()), "someone else's table");
  EXPECT_EQ(read_all((out / "keep.txt").string()), "kept");
  EXPECT_NE(read_all(r.log).find("dspbr: interrupted (SIGINT): nothing was written\n"), std::string::npos)
      << read_all(r.log);
}

// Missing parents are created one by one and removed again, the folder that existed kept.
TEST(Interrupt, LutRemovesTheParentsItCreated) {
  const fs::path root = fs::path(::testing::TempDir()) / "interrupt_parents";
  fs::remove_all(root);
  fs::create_directories(root);
  const fs::path out = root / "a" / "b" / "c";
  const LutRun r = start(out.string(), root.string() + ".log");
  EXPECT_EQ(interrupt(r, out, SIGTERM), 128 + SIGTERM) << read_all(r.log);
  EXPECT_TRUE(fs::is_empty(root)) << read_all(r.log);
  EXPECT_NE(read_all(r.log).find("removed the 3 folder(s) it created"), std::string::npos) << read_all(r.log);
}

// Issue 45 (#5): an interrupt at the very start (pending before the tool runs) leaves no staging
// folder and no folder, and the run exits 128 + signal with one line. Before the handlers were
// installed ahead of the folder, the signal stayed blocked and the run went on.
TEST(Interrupt, AnInterruptAtTheStartLeavesNothing) {
  for (int sig : {SIGINT, SIGTERM}) {
    const fs::path dir = fs::path(::testing::TempDir()) / ("interrupt_start_" + std::to_string(sig));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const LutRun r = start((dir / "new" / "out").string(), (dir.parent_path() / ("interrupt_start.log")).string(), sig);
    int status = 0;
    waitpid(r.pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
    const std::string log = read_all(r.log);
    // One line (the folders may have been created and removed again: the handler waits for them).
    EXPECT_EQ(log.rfind(std::string("dspbr: interrupted (") + (sig == SIGINT ? "SIGINT" : "SIGTERM") +
                            "): nothing was written", 0),
              0u)
        << log;
    EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 1) << log;
    EXPECT_EQ(log.find(".dspbr-staging"), std::string::npos) << log;
    EXPECT_TRUE(fs::is_empty(dir)) << "left behind in " << dir;
  }
}

// A child process (here the report script, a stand-in that sleeps) is stopped with the run: the
// run exits 128 + signal at once, leaves no folder, and the child is gone (std::system ignored
// SIGINT in dspbr while the script ran: the run went on, committed and exited 0).
TEST(Interrupt, TheReportScriptIsStoppedWithTheRun) {
  for (int sig : {SIGINT, SIGTERM}) {
    const fs::path dir = fs::path(::testing::TempDir()) / ("interrupt_script_" + std::to_string(sig));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string vectors = std::string(DSPBR_SOURCE_DIR) + "/tests/data/conformance/vectors-small.json";
    const std::string results = (dir / "r.json").string();
    ASSERT_EQ(std::system(("'" + std::string(DSPBR_EXE) + "' conformance reference '" + vectors + "' --out '" + results +
                           "' > /dev/null").c_str()),
              0);
    const fs::path fake = dir / "python", pid_file = dir / "script.pid";
    // `python -c "import ..."` (the check before the work) succeeds; the script itself sleeps.
    std::ofstream(fake) << "#!/bin/sh\n[ \"$1\" = -c ] && exit 0\necho $$ > '" << pid_file.string() << "'\nexec sleep 30\n";
    fs::permissions(fake, fs::perms::owner_all);
    const fs::path out = dir / "report";
    const LutRun r = start_args({DSPBR_EXE, "conformance", "check", vectors, results, "--python", fake.string(), "--out",
                                 out.string()},
                                (dir / "log").string());
    ASSERT_TRUE(wait_for([&] { return fs::exists(pid_file) && fs::file_size(pid_file) > 0; }));
    const pid_t script = std::stoi(read_all(pid_file));
    kill(r.pid, sig);
    int status = 0;
    waitpid(r.pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig) << read_all(r.log);
    EXPECT_FALSE(fs::exists(out)) << read_all(r.log);
    EXPECT_TRUE(wait_for([&] { return ::kill(script, 0) != 0; })) << "the report script outlived the run";
  }
}
