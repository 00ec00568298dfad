// Never leave a half-written output, never write through a planted link: a file is written into
// a fresh private folder next to its target (mkdtemp, mode 0700), then renamed over the target
// (atomic on POSIX file systems; rename(2) replaces a symbolic link at the target instead of
// following it).
#pragma once
#include <functional>
#include <stdexcept>
#include <string>

namespace dspbr {

// The place a file goes is taken by something a file must not replace (a folder, FIFO, device,
// socket, or a link to one), or is no file name: a problem of the input the run was given, not a
// failure of the run (`dspbr` exits 2 with it, as for any bad input).
struct NotReplaceable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Calls write(tmp_path) and renames tmp_path to path when it returns normally; removes the
// temporary file and folder and rethrows when it throws. Creates missing parent folders. Throws
// NotReplaceable, before writing, when path exists and is not a regular file or a link to one
// (a FIFO or a device would otherwise be replaced by a regular file).
void write_atomically(const std::string& path, const std::function<void(const std::string& tmp_path)>& write);

// Throws NotReplaceable ("cannot write 'path': it exists and is not a regular file ...") when
// path exists and is neither a regular file nor a link to one or to nothing: a FIFO, a device, a
// socket, a folder or a link to one of them (/dev/stdout) would be replaced by the rename. A link
// to a regular file, or a dangling one, is replaced (never written through).
void require_replaceable(const std::string& path);

// Writes a text file atomically.
void write_text_atomically(const std::string& path, const std::string& text);

// Writes `text` to `file` (not atomically: a file in a staging folder, or write_atomically's
// temporary). Throws std::runtime_error "cannot write '<named_as>': <system's reason>", naming the
// file as the user will know it (the temporary is gone when the message is read).
void write_text_file(const std::string& file, const std::string& text, const std::string& named_as);

}  // namespace dspbr
