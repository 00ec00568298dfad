// Never leave a half-written output: write to a temporary name in the target folder, then
// rename over the target (atomic on POSIX file systems).
#pragma once
#include <functional>
#include <string>

namespace dspbr {

// Calls write(tmp_path) and renames tmp_path to path when it returns normally; removes the
// temporary file and rethrows when it throws. Creates missing parent folders.
void write_atomically(const std::string& path, const std::function<void(const std::string& tmp_path)>& write);

// Writes a text file atomically.
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace dspbr
