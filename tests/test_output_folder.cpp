// The output folder of a run (src/dspbr/io/output_folder.h) changes only by moving a complete new
// set into it: links planted at the target names are replaced, not written through; a failed or
// abandoned run leaves the folder as it found it and removes only what it created.
#include <gtest/gtest.h>
#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <atomic>
#include <thread>
#include <stdexcept>
#include <string>

#include "dspbr/io/output_folder.h"
#include "test_files.h"

using namespace dspbr;
namespace fs = std::filesystem;

namespace {

fs::path fresh(const std::string& name) {
  const fs::path p = fs::path(::testing::TempDir()) / ("output_folder_" + name);
  fs::remove_all(p);
  return p;
}

}  // namespace

TEST(OutputFolder, CommitMovesTheSetAndKeepsOtherFiles) {
  const fs::path dir = fresh("commit");
  write(dir / "keep.txt", "someone else's");
  write(dir / "a.json", "old");
  {
    OutputFolder out(dir.string(), "--out");
    EXPECT_EQ(fs::path(out.staging()).parent_path(), dir);
    write(fs::path(out.staging()) / "a.json", "new");
    write(fs::path(out.staging()) / "renderer" / "b.exr", "b");
    // Nothing is visible in the folder before the commit.
    EXPECT_EQ(read_all(dir / "a.json"), "old");
    EXPECT_FALSE(fs::exists(dir / "renderer"));
    EXPECT_EQ(out.commit(), (std::vector<std::string>{"a.json", "renderer/b.exr"}));
    EXPECT_EQ(out.discard(), "the outputs were in place already");
  }
  EXPECT_EQ(listing(dir), (std::set<std::string>{"a.json", "keep.txt", "renderer", "renderer/b.exr"}));
  EXPECT_EQ(read_all(dir / "a.json"), "new");
  EXPECT_EQ(read_all(dir / "keep.txt"), "someone else's");
}

TEST(OutputFolder, AbandonedRunRemovesOnlyTheFoldersItCreated) {
  const fs::path root = fresh("nested");
  fs::create_directories(root);
  write(root / "other.txt", "x");
  const fs::path dir = root / "a" / "b" / "c";
  {
    OutputFolder out(dir.string(), "--out");
    EXPECT_TRUE(fs::is_directory(dir));
    write(fs::path(out.staging()) / "t.json", "unfinished");
    const std::string what = out.discard();
    EXPECT_EQ(what, "removed its unfinished outputs (1 file(s) and folder(s)); removed the 3 folder(s) it created ('" +
                        dir.string() + "')");
  }
  EXPECT_EQ(listing(root), (std::set<std::string>{"other.txt"}));
  // A folder it created but someone else wrote into meanwhile is kept.
  {
    OutputFolder out(dir.string(), "--out");
    write(root / "a" / "theirs.txt", "x");
    EXPECT_EQ(out.discard(), "nothing was written; removed the 2 folder(s) it created ('" + dir.string() + "')");
  }
  EXPECT_EQ(listing(root), (std::set<std::string>{"a", "a/theirs.txt", "other.txt"}));
}

TEST(OutputFolder, TheDestructorDiscards) {
  const fs::path dir = fresh("destructor");
  {
    OutputFolder out(dir.string(), "--out");
    write(fs::path(out.staging()) / "t.json", "unfinished");
  }
  EXPECT_FALSE(fs::exists(dir));
}

// An interrupt discards while the run's thread still writes into the staging folder: discard()
// stops the writers first (the hook), then removes; a file created while the removal listed the
// folder had kept it (the tenth fresh tester's pass: an interrupted `shader`).
TEST(OutputFolder, DiscardStopsTheWritersBeforeRemoving) {
  int hooks = 0;
  for (int round = 0; round < 40; ++round) {
    const fs::path dir = fresh("writers");
    OutputFolder out(dir.string(), "--out");
    const std::string staging = out.staging();
    std::atomic<bool> stop{false};
    std::thread writer([&] {
      for (int i = 0; !stop.load(); ++i) {
        std::ofstream(fs::path(staging) / ("f" + std::to_string(i % 64))) << i;
        std::error_code ec;
        fs::create_directories(fs::path(staging) / "plots", ec);
      }
    });
    std::this_thread::sleep_for(std::chrono::microseconds(200 * (round % 5)));
    out.discard([&] {
      ++hooks;
      EXPECT_TRUE(fs::exists(staging));  // nothing removed yet
      stop = true;
      writer.join();
    });
    stop = true;  // (a discard that did not call the hook left the writer running until here)
    if (writer.joinable()) writer.join();
    EXPECT_FALSE(fs::exists(staging)) << "round " << round;
    EXPECT_FALSE(fs::exists(dir)) << "round " << round;
    fs::remove_all(dir);
  }
  EXPECT_EQ(hooks, 40);
}

// A symbolic link planted at an output name points at a file the run must not touch.
TEST(OutputFolder, APlantedLinkIsReplacedNotWrittenThrough) {
  const fs::path dir = fresh("planted");
  const fs::path victim = fresh("planted_victim.txt");
  write(victim, "precious");
  fs::create_directories(dir);
  fs::create_symlink(victim, dir / "a.json");
  OutputFolder out(dir.string(), "--out");
  write(fs::path(out.staging()) / "a.json", "new");
  out.commit();
  EXPECT_EQ(read_all(victim), "precious");
  EXPECT_FALSE(fs::is_symlink(dir / "a.json"));
  EXPECT_EQ(read_all(dir / "a.json"), "new");
}

TEST(OutputFolder, ALinkedSubFolderRefusesTheWholeSet) {
  const fs::path dir = fresh("linked_sub");
  const fs::path elsewhere = fresh("linked_sub_elsewhere");
  fs::create_directories(elsewhere);
  fs::create_directories(dir);
  write(dir / "a.json", "old");
  fs::create_directory_symlink(elsewhere, dir / "renderer");
  OutputFolder out(dir.string(), "--out");
  write(fs::path(out.staging()) / "a.json", "new");
  write(fs::path(out.staging()) / "renderer" / "b.exr", "b");
  try {
    out.commit();
    ADD_FAILURE() << "commit through a linked sub-folder";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "'" + (dir / "renderer").string() + "' is not a folder (a symbolic link or a file): nothing written");
  }
  EXPECT_TRUE(fs::is_empty(elsewhere));
  EXPECT_EQ(read_all(dir / "a.json"), "old");  // no part of the set was moved
  EXPECT_EQ(listing(dir), (std::set<std::string>{"a.json", "renderer"}));
}

TEST(OutputFolder, AFileInTheWayIsNamed) {
  const fs::path file = fresh("a_file");
  write(file, "x");
  try {
    OutputFolder out(file.string(), "--out");
    ADD_FAILURE() << "a file accepted as output folder";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "--out: '" + file.string() + "' exists and is not a folder");
  }
  EXPECT_EQ(read_all(file), "x");
  const fs::path dir = fresh("folder_in_the_way");
  fs::create_directories(dir / "a.json");
  OutputFolder out(dir.string(), "--out");
  write(fs::path(out.staging()) / "a.json", "new");
  EXPECT_THROW(out.commit(), std::runtime_error);
  EXPECT_TRUE(fs::is_directory(dir / "a.json"));
}

// Issue 45 (#8): every path the kernel resolves is a valid --out, spelled as given.
namespace {
void commit_one(const std::string& dir) {
  OutputFolder out(dir, "--out");
  write(fs::path(out.staging()) / "a.json", "new");
  EXPECT_EQ(out.commit(), (std::vector<std::string>{"a.json"}));
}
}  // namespace

TEST(OutputFolder, ATrailingSlashIsTheFolder) {
  const fs::path base = fresh("trailing_slash");
  commit_one((base / "new").string() + "/");
  EXPECT_EQ(listing(base), (std::set<std::string>{"new", "new/a.json"}));
  commit_one((base / "new").string() + "//");  // existing, two slashes
  EXPECT_EQ(read_all(base / "new" / "a.json"), "new");
}

TEST(OutputFolder, LinkDotDotIsResolvedByTheKernel) {
  const fs::path base = fresh("link_dotdot");
  fs::create_directories(base / "real" / "inner");
  fs::create_directory_symlink(base / "real" / "inner", base / "link");
  // link/.. is real/ (the link's parent), not base/ as lexical normalization would make it.
  commit_one((base / "link" / ".." / "new").string());
  EXPECT_TRUE(fs::exists(base / "real" / "new" / "a.json"));
  EXPECT_FALSE(fs::exists(base / "new"));
  commit_one((base / "x" / "." / "y").string());
  EXPECT_TRUE(fs::exists(base / "x" / "y" / "a.json"));
}

TEST(OutputFolder, WorksInAWorkingDirectoryDeeperThanPathMax) {
  const fs::path base = fresh("deep");
  fs::create_directories(base);
  const int home = ::open(".", O_RDONLY | O_DIRECTORY);
  ASSERT_GE(home, 0);
  ASSERT_EQ(::chdir(base.c_str()), 0);
  const std::string part(200, 'd');
  for (int i = 0; i < 25; ++i) {  // 25 x 201 bytes > PATH_MAX (4096)
    ASSERT_EQ(::mkdir(part.c_str(), 0777), 0);
    ASSERT_EQ(::chdir(part.c_str()), 0);
  }
  char buf[64];
  EXPECT_EQ(::getcwd(buf, sizeof buf), nullptr);  // the kernel's path is too long for getcwd
  commit_one(".");
  commit_one("sub/");
  EXPECT_TRUE(fs::exists("a.json"));
  EXPECT_TRUE(fs::exists("sub/a.json"));
  ASSERT_EQ(::fchdir(home), 0);
  ::close(home);
  // remove the deep tree from the inside out (remove_all would need the long path)
  std::error_code ec;
  fs::remove_all(base, ec);
}

// Issue 45 (#7): a commit is all or nothing when a rename fails part-way (another filesystem, a
// read-only sub-folder, a full disk). The failures are injected: this executable's rename and
// linkat stand in for libc's (the library is linked into it statically), failing the calls armed
// by number and passing every other call through.
namespace faults {
std::map<int, int> rename_fail, linkat_fail;  // call number from arming -> errno
int rename_calls = 0, linkat_calls = 0;
void arm(std::map<int, int> renames, std::map<int, int> links = {}) {
  rename_fail = std::move(renames), linkat_fail = std::move(links);
  rename_calls = linkat_calls = 0;
}
bool fails(std::map<int, int>& table, int& calls) {
  const auto it = table.find(calls++);
  if (it == table.end()) return false;
  errno = it->second;
  return true;
}
}  // namespace faults

extern "C" int rename(const char* from, const char* to) noexcept {
  using Fn = int (*)(const char*, const char*);
  static const Fn real = reinterpret_cast<Fn>(::dlsym(RTLD_NEXT, "rename"));
  return faults::fails(faults::rename_fail, faults::rename_calls) ? -1 : real(from, to);
}

extern "C" int linkat(int olddirfd, const char* from, int newdirfd, const char* to, int flags) noexcept {
  using Fn = int (*)(int, const char*, int, const char*, int);
  static const Fn real = reinterpret_cast<Fn>(::dlsym(RTLD_NEXT, "linkat"));
  return faults::fails(faults::linkat_fail, faults::linkat_calls) ? -1 : real(olddirfd, from, newdirfd, to, flags);
}

namespace {

// a.json and c.json in place, the set a, b, c (moved in that order, sorted).
fs::path commit_failing(const std::string& name, std::map<int, int> renames, std::map<int, int> links,
                        std::string& message) {
  const fs::path dir = fresh(name);
  write(dir / "a.json", "old a");
  write(dir / "c.json", "old c");
  OutputFolder out(dir.string(), "--out");
  for (const char* f : {"a.json", "b.json", "c.json"}) write(fs::path(out.staging()) / f, std::string("new ") + f[0]);
  faults::arm(std::move(renames), std::move(links));
  try {
    out.commit();
    ADD_FAILURE() << "the commit succeeded";
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  faults::arm({});
  return dir;
}

}  // namespace

TEST(OutputFolder, AFailingRenamePutsBackWhatMovedBefore) {
  for (const int err : {EXDEV, EACCES, ENOSPC}) {
    std::string message;
    const fs::path dir = commit_failing("rollback", {{2, err}}, {}, message);  // c.json's rename
    EXPECT_EQ(message, "cannot move 'c.json' into '" + dir.string() + "': " + std::strerror(err) +
                           ": nothing written (the files moved before were put back)");
    EXPECT_EQ(listing(dir), (std::set<std::string>{"a.json", "c.json"}));  // b.json removed, no staging
    EXPECT_EQ(read_all(dir / "a.json"), "old a");
    EXPECT_EQ(read_all(dir / "c.json"), "old c");
  }
  // The first rename failing moves nothing; the last one failing puts two back.
  std::string message;
  fs::path dir = commit_failing("rollback_first", {{0, EACCES}}, {}, message);
  EXPECT_EQ(listing(dir), (std::set<std::string>{"a.json", "c.json"}));
  EXPECT_EQ(read_all(dir / "a.json"), "old a");
  // Without a failure the same set commits (the fault table is what failed it).
  dir = fresh("rollback_none");
  write(dir / "a.json", "old a");
  {
    OutputFolder out(dir.string(), "--out");
    write(fs::path(out.staging()) / "a.json", "new a");
    EXPECT_EQ(out.commit(), (std::vector<std::string>{"a.json"}));
  }
  EXPECT_EQ(listing(dir), (std::set<std::string>{"a.json"}));
  EXPECT_EQ(read_all(dir / "a.json"), "new a");
}

TEST(OutputFolder, AFileThatCannotBeKeptStopsTheCommitBeforeAnyMove) {
  // c.json on another filesystem: its link for the rollback fails (EXDEV) before any rename.
  std::string message;
  const fs::path dir = commit_failing("unkept", {}, {{1, EXDEV}}, message);
  EXPECT_EQ(message, "cannot replace '" + (dir / "c.json").string() + "': " + std::strerror(EXDEV) + ": nothing written");
  EXPECT_EQ(listing(dir), (std::set<std::string>{"a.json", "c.json"}));
  EXPECT_EQ(read_all(dir / "a.json"), "old a");
  EXPECT_EQ(read_all(dir / "c.json"), "old c");
}

TEST(OutputFolder, WhatCannotBePutBackIsNamedAndKept) {
  // c.json's rename fails, then putting a.json back fails too (rename 3): the message names the
  // folder that keeps the old a.json, and nothing of it is lost.
  std::string message;
  const fs::path dir = commit_failing("lost", {{2, ENOSPC}, {3, EACCES}}, {}, message);
  const std::string head = "cannot move 'c.json' into '" + dir.string() + "': " + std::strerror(ENOSPC) +
                           "; could not put back a.json: the replaced files are in '";
  ASSERT_EQ(message.substr(0, head.size()), head);
  const fs::path kept = message.substr(head.size(), message.size() - head.size() - 1);
  EXPECT_EQ(kept.parent_path(), dir);
  EXPECT_EQ(read_all(kept / "a.json"), "old a");
  EXPECT_EQ(read_all(dir / "a.json"), "new a");
  EXPECT_EQ(read_all(dir / "c.json"), "old c");
  EXPECT_FALSE(fs::exists(dir / "b.json"));
}

// A FIFO (or a link to a device) at a target name refuses the set before any file moves, as a
// folder there does (rename(2) would replace it by a regular file).
TEST(OutputFolder, AFifoAtATargetRefusesTheSet) {
  const fs::path dir = fresh("fifo");
  fs::create_directories(dir);
  write(dir / "a.json", "old");
  ASSERT_EQ(::mkfifo((dir / "b.json").c_str(), 0600), 0);
  fs::create_symlink("/dev/null", dir / "c.json");
  for (const std::string name : {"b.json", "c.json"}) {
    OutputFolder out(dir.string(), "--out");
    write(fs::path(out.staging()) / "a.json", "new");
    write(fs::path(out.staging()) / name, "new");
    try {
      out.commit();
      ADD_FAILURE() << name << " was replaced";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "cannot write '" + (dir / name).string() +
                                           "': it exists and is not a regular file (a folder, FIFO, device, socket or "
                                           "a link to one); name a file path: nothing written");
    }
  }
  EXPECT_EQ(read_all(dir / "a.json"), "old");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(dir / "b.json")));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "c.json")));
  EXPECT_EQ(listing(dir), (std::set<std::string>{"a.json", "b.json", "c.json"}));
}
