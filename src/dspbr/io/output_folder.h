// An output folder that a run changes only by moving a complete new set of files into it
// (docs/limits.md, "Output folders"). The run writes into a private staging folder inside the
// output folder (mkdtemp: a fresh name, mode 0700, so nothing can be planted in it); commit()
// renames each file into place; discard() (a failure, an interrupt, or no commit) removes the
// staging folder and the folders this object created, each only when empty. Nothing else is
// ever deleted, truncated or written through: a file in place is replaced by rename(2), which
// replaces a symbolic link rather than following it, and a sub-folder that is a symbolic link is
// refused.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dspbr {

class OutputFolder {
 public:
  // Creates `dir` and its missing parents unless `dir` is a folder (or a link to one) already,
  // then the staging folder. Throws std::invalid_argument "<option>: <problem>" when `dir`
  // exists and is not a folder, or a folder cannot be created or written.
  OutputFolder(const std::string& dir, const std::string& option);
  ~OutputFolder();  // discard() unless committed
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  OutputFolder(OutputFolder&&) noexcept = default;

  const std::string& dir() const;      // the output folder, as given
  const std::string& staging() const;  // where the run writes its files

  // Moves every file of the staging folder to the same relative path in dir() (creating
  // sub-folders), removes the staging folder; returns the relative paths moved, sorted. All or
  // nothing: throws std::runtime_error naming the file when one cannot be moved, after putting
  // back the files moved before it (docs/limits.md, "Output folders"); the rest is discarded.
  // NotReplaceable (io/atomic_file.h), before any move, when a file's place is a folder, a FIFO, a
  // device or a link to one, or a sub-folder's place is not a real folder.
  std::vector<std::string> commit();

  // Removes the staging folder and the folders the constructor created (when empty); says what
  // it did ("nothing was written", "removed ..."). Thread-safe (an interrupt handler calls it
  // while the run writes); a no-op after commit(). `stop_writers`, when given, runs first, once no
  // commit is in progress: it must stop every thread that may still write into the staging folder
  // (a file created while the folder is being removed would keep it).
  std::string discard(const std::function<void()>& stop_writers = {});

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace dspbr
