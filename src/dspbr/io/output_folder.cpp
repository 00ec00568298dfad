#include "dspbr/io/output_folder.h"

#include "dspbr/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace dspbr {

namespace fs = std::filesystem;

struct OutputFolder::State {
  std::string dir, staging;
  std::string kept;  // commit's folder of links to the files the set replaces (rollback)
  std::vector<fs::path> created;  // folders this object made, outermost first
  std::mutex mutex;
  bool done = false;  // committed or discarded

  // Removes the staging folder (made by this run, mode 0700: only its files are in it) and the
  // created parents when they are empty (rmdir fails on anything else: nothing is lost).
  std::string remove_own() {
    std::error_code ec;
    const std::uintmax_t n = staging.empty() ? 0 : fs::remove_all(staging, ec);
    if (!kept.empty()) fs::remove_all(kept, ec);  // links only: the files they name are in place
    std::size_t parents = 0;
    for (auto it = created.rbegin(); it != created.rend(); ++it)
      if (::rmdir(it->c_str()) == 0) ++parents;
    done = true;
    std::string what = n > 1 ? "removed its unfinished outputs (" + std::to_string(n - 1) + " file(s) and folder(s))"
                             : "nothing was written";
    if (parents > 0) what += "; removed the " + std::to_string(parents) + " folder(s) it created ('" + dir + "')";
    else if (!created.empty()) what += "; kept '" + dir + "' (not empty)";
    return what;
  }
};

OutputFolder::OutputFolder(const std::string& dir, const std::string& option) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.dir = dir;
  if (dir.empty()) throw std::invalid_argument(option + ": give a folder name");
  std::error_code ec;
  const fs::path target(dir);
  if (fs::exists(target, ec) && !fs::is_directory(target, ec))
    throw std::invalid_argument(option + ": '" + dir + "' exists and is not a folder");
  // Create the missing folders one by one, outermost first, remembering them for discard(). The
  // path is walked as given, each prefix resolved by the kernel (never made absolute or lexically
  // normalized: `link/../new` is the kernel's, not `new`; a working directory deeper than PATH_MAX
  // works); a trailing slash, "." and ".." name no folder of their own.
  std::vector<fs::path> missing;
  for (fs::path p = target; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    if (p == p.parent_path()) break;
    const std::string name = p.filename().string();
    if (!name.empty() && name != "." && name != "..") missing.push_back(p);
  }
  std::reverse(missing.begin(), missing.end());
  for (const fs::path& p : missing) {
    if (::mkdir(p.c_str(), 0777) != 0) {
      const int err = errno;
      if (err == EEXIST && fs::is_directory(p, ec)) continue;  // the same folder by another spelling
      s.remove_own();
      throw std::invalid_argument(option + ": cannot create folder '" + p.string() + "': " + std::strerror(err));
    }
    s.created.push_back(p);
  }
  std::string templ = (target / ".dspbr-staging-XXXXXX").string();
  if (::mkdtemp(templ.data()) == nullptr) {
    const int err = errno;
    s.remove_own();
    throw std::invalid_argument(option + ": cannot write into folder '" + dir + "': " + std::strerror(err));
  }
  s.staging = templ;
}

OutputFolder::~OutputFolder() {
  if (state_) discard();
}

const std::string& OutputFolder::dir() const { return state_->dir; }
const std::string& OutputFolder::staging() const { return state_->staging; }

namespace {

// `p` is a real folder (lstat: not a symbolic link to one).
bool is_real_folder(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

}  // namespace

std::vector<std::string> OutputFolder::commit() {
  State& s = *state_;
  const std::lock_guard<std::mutex> lock(s.mutex);
  if (s.done) throw std::logic_error("OutputFolder::commit after commit or discard");
  std::vector<std::string> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(s.staging, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    if (it->is_regular_file()) files.push_back(it->path().lexically_relative(s.staging).string());  // no getcwd
  std::sort(files.begin(), files.end());
  // First every check and sub-folder, then the renames: a refused set moves no file at all.
  for (const std::string& rel : files) {
    // Sub-folders of the output folder: real folders, created when missing, never a link.
    fs::path folder = fs::path(s.dir);
    for (const fs::path& part : fs::path(rel).parent_path()) {
      folder /= part;
      if (::mkdir(folder.c_str(), 0777) == 0) {
        s.created.push_back(folder);  // removed again (when empty) if the set is refused
      } else if (errno != EEXIST) {
        const int err = errno;
        s.remove_own();
        throw std::runtime_error("cannot create folder '" + folder.string() + "': " + std::strerror(err));
      }
      if (!is_real_folder(folder)) {
        s.remove_own();
        throw NotReplaceable("'" + folder.string() + "' is not a folder (a symbolic link or a file): nothing written");
      }
    }
    // rename(2) replaces a file or a symbolic link, not a folder.
    if (is_real_folder(fs::path(s.dir) / rel)) {
      s.remove_own();
      throw NotReplaceable("'" + (fs::path(s.dir) / rel).string() + "' is a folder: nothing written");
    }
    // ... nor should it replace a FIFO, a device or a socket (or a link to one) by a regular file.
    try {
      require_replaceable((fs::path(s.dir) / rel).string());
    } catch (const NotReplaceable& e) {
      s.remove_own();
      throw NotReplaceable(std::string(e.what()) + ": nothing written");
    }
  }
  // All or nothing: every file in place that the set replaces is first hard-linked into a folder
  // of this run's (linkat without AT_SYMLINK_FOLLOW: a symbolic link is kept as the link); a file
  // that cannot be linked (another filesystem, where the rename would fail too) stops the commit
  // before anything moved. When a rename then fails (EACCES, EXDEV, ENOSPC, ...), the files moved
  // so far are put back: each replaced one renamed back from its link, each new one removed.
  std::vector<bool> replaces(files.size(), false);
  for (std::size_t k = 0; k < files.size(); ++k) {
    const fs::path target = fs::path(s.dir) / files[k];
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0) continue;  // a new file
    if (s.kept.empty()) {
      std::string templ = (fs::path(s.dir) / ".dspbr-kept-XXXXXX").string();
      if (::mkdtemp(templ.data()) == nullptr) {
        const int err = errno;
        s.remove_own();
        throw std::runtime_error("cannot write into folder '" + s.dir + "': " + std::strerror(err) + ": nothing written");
      }
      s.kept = templ;
    }
    const fs::path link = fs::path(s.kept) / files[k];
    fs::create_directories(link.parent_path(), ec);  // inside the run's own folder
    if (::linkat(AT_FDCWD, target.c_str(), AT_FDCWD, link.c_str(), 0) != 0) {
      const int err = errno;
      s.remove_own();
      throw std::runtime_error("cannot replace '" + target.string() + "': " + std::strerror(err) + ": nothing written");
    }
    replaces[k] = true;
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    const fs::path target = fs::path(s.dir) / files[k];
    if (::rename((fs::path(s.staging) / files[k]).c_str(), target.c_str()) == 0) continue;
    const int err = errno;
    std::string lost;  // files that could not be put back
    for (std::size_t j = k; j-- > 0;) {
      const fs::path moved = fs::path(s.dir) / files[j];
      const bool back = replaces[j] ? ::rename((fs::path(s.kept) / files[j]).c_str(), moved.c_str()) == 0
                                    : ::unlink(moved.c_str()) == 0;
      if (!back) lost += (lost.empty() ? "" : ", ") + files[j];
    }
    std::string what = "cannot move '" + files[k] + "' into '" + s.dir + "': " + std::strerror(err);
    if (lost.empty()) {
      s.remove_own();
      throw std::runtime_error(what + ": nothing written (the files moved before were put back)");
    }
    // Keep the links to what could not be restored, and say where they are.
    const std::string kept = s.kept;
    s.kept.clear();
    s.remove_own();
    throw std::runtime_error(what + "; could not put back " + lost + ": the replaced files are in '" + kept + "'");
  }
  if (!s.kept.empty()) fs::remove_all(s.kept, ec), s.kept.clear();  // links to the replaced files
  fs::remove_all(s.staging, ec);  // the emptied staging folders
  s.done = true;
  return files;
}

std::string OutputFolder::discard(const std::function<void()>& stop_writers) {
  State& s = *state_;
  const std::lock_guard<std::mutex> lock(s.mutex);
  if (s.done) return "the outputs were in place already";
  if (stop_writers) stop_writers();
  return s.remove_own();
}

}  // namespace dspbr
