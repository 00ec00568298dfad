// Never leave a half-written output, never write through a planted link: a file is written into
// a fresh private folder next to its target (mkdtemp, mode 0700), then renamed over the target
// (atomic on POSIX file systems; rename(2) replaces a symbolic link at the target instead of
// following it).
#pragma once
#include <functional>
#include <string>

namespace dspbr {

// Calls write(tmp_path) and renames tmp_path to path when it returns normally; removes the
// temporary file and folder and rethrows when it throws. Creates missing parent folders.
void write_atomically(const std::string& path, const std::function<void(const std::string& tmp_path)>& write);

// Writes a text file atomically.
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace dspbr
