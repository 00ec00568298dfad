// The output folder of a run (src/dspbr/io/output_folder.h) changes only by moving a complete new
// set into it: links planted at the target names are replaced, not written through; a failed or
// abandoned run leaves the folder as it found it and removes only what it created.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
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
