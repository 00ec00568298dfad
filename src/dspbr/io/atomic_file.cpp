#include "dspbr/io/atomic_file.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace dspbr {

namespace fs = std::filesystem;

void require_replaceable(const std::string& path) {
  const fs::path target(path);
  std::error_code ec;
  const fs::file_status own = fs::symlink_status(target, ec);
  if (ec || !fs::exists(own) || fs::is_regular_file(own)) return;
  if (fs::is_symlink(own)) {
    const fs::file_status to = fs::status(target, ec);
    if (ec || !fs::exists(to) || fs::is_regular_file(to)) return;
  }
  throw NotReplaceable("cannot write '" + path + "': it exists and is not a regular file (a folder, FIFO, device, "
                           "socket or a link to one); name a file path");
}

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  const fs::path target(path);
  if (!target.has_filename()) throw NotReplaceable("cannot write '" + path + "': give a file name, not a folder");
  require_replaceable(path);
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  // The missing parent folders, created one by one and removed again (when empty) on failure.
  std::vector<fs::path> created;
  for (fs::path p = parent; !p.empty() && !fs::exists(fs::symlink_status(p, ec)); p = p.parent_path()) created.push_back(p);
  std::reverse(created.begin(), created.end());
  auto remove_created = [&] {
    for (auto it = created.rbegin(); it != created.rend(); ++it) ::rmdir(it->c_str());
  };
  for (std::size_t k = 0; k < created.size(); ++k)
    if (::mkdir(created[k].c_str(), 0777) != 0) {
      const int err = errno;
      const std::string folder = created[k].string();
      created.resize(k);
      remove_created();
      throw std::runtime_error("cannot create folder '" + folder + "': " + std::strerror(err));
    }
  std::string folder = (parent / ".dspbr-tmp-XXXXXX").string();
  if (::mkdtemp(folder.data()) == nullptr) {
    const int err = errno;
    remove_created();
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(err));
  }
  // Keep the file name (and its extension last: image writers pick the format from it).
  const fs::path tmp = fs::path(folder) / target.filename();
  auto clean = [&] {
    fs::remove(tmp, ec);
    ::rmdir(folder.c_str());
    remove_created();
  };
  try {
    write(tmp.string());
  } catch (...) {
    clean();
    throw;
  }
  try {
    require_replaceable(path);  // again: it may have appeared while the file was written
  } catch (...) {
    clean();
    throw;
  }
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    const int err = errno;
    clean();
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(err));
  }
  ::rmdir(folder.c_str());
}

void write_text_file(const std::string& file, const std::string& text, const std::string& named_as) {
  errno = 0;
  std::ofstream out(file, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write '" + named_as + "': " + std::strerror(errno ? errno : EIO));
  out << text;
  out.flush();
  const int write_error = errno;
  out.close();
  if (!out)
    throw std::runtime_error("cannot write '" + named_as + "': " + std::strerror(write_error ? write_error : errno ? errno : EIO));
}

void write_text_atomically(const std::string& path, const std::string& text) {
  write_atomically(path, [&](const std::string& tmp) { write_text_file(tmp, text, path); });
}

}  // namespace dspbr
