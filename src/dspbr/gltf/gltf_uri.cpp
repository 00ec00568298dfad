#include "dspbr/gltf/gltf_uri.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <deque>
#include <filesystem>
#include <stdexcept>

#include "dspbr/io/message.h"

namespace dspbr::gltf {

namespace fs = std::filesystem;

namespace {

// Symbolic links followed while resolving one URI (Linux's own limit, MAXSYMLINKS, is 40).
constexpr int kMaxLinks = 40;

int hex_value(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : std::tolower(static_cast<unsigned char>(c)) - 'a' + 10;
}

// `p` (lexically normal, absolute) lies in `base` (lexically normal, absolute) or is it.
bool inside(const fs::path& p, const fs::path& base) {
  auto b = base.begin(), q = p.begin();
  for (; b != base.end(); ++b, ++q)
    if (q == p.end() || *q != *b) return false;
  return true;
}

}  // namespace

std::string percent_decode(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '\0') throw std::invalid_argument("holds a NUL byte");  // C paths end there: "..\0x" would be ".."
    if (uri[i] != '%') {
      out += uri[i];
      continue;
    }
    if (i + 2 >= uri.size() || !std::isxdigit(static_cast<unsigned char>(uri[i + 1])) ||
        !std::isxdigit(static_cast<unsigned char>(uri[i + 2])))
      throw std::invalid_argument("malformed percent-encoding (RFC 3986: '%' and two hexadecimal digits)");
    const char c = static_cast<char>(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
    if (c == '\0') throw std::invalid_argument("encodes a NUL byte");
    out += c;
    i += 2;
  }
  return out;
}

std::string resolve_local_uri(const std::string& gltf_path, const std::string& uri) {
  return LocalUriResolver(gltf_path).resolve(uri);
}

std::string LocalUriResolver::resolve(const std::string& uri) {
  auto refuse = [&](const std::string& why) { return std::invalid_argument("URI '" + quote_input(uri) + "' " + why); };
  std::string decoded;
  try {
    decoded = percent_decode(uri);
  } catch (const std::invalid_argument& e) {
    throw refuse(e.what());
  }
  if (decoded.empty()) throw refuse("is empty");
  if (decoded[0] == '/' || decoded[0] == '\\') throw refuse("is an absolute path; only files inside the glTF's folder are read");
  if (base_.empty()) {
    std::error_code ec;
    const fs::path folder = fs::path(gltf_path_).parent_path();
    base_ = fs::canonical(folder.empty() ? fs::path(".") : folder, ec).string();
    if (ec || base_.empty()) {
      base_.clear();
      throw refuse("cannot be resolved: the glTF's folder cannot be read");
    }
  }
  const fs::path base(base_);
  std::deque<fs::path> todo;
  for (const fs::path& part : fs::path(decoded)) todo.push_back(part);
  fs::path current = base;
  int links = 0;
  bool missing = false;  // a component did not exist: nothing below it can exist (no lstat until "..")
  while (!todo.empty()) {
    const fs::path part = todo.front();
    todo.pop_front();
    if (part.empty() || part == ".") continue;
    if (part == "..") {
      if (current == base) throw refuse("leaves the glTF's folder");
      current = current.parent_path();
      missing = false;  // back in a folder that exists (or that is checked again below)
      continue;
    }
    const fs::path next = current / part;
    struct stat st {};
    if (missing || ::lstat(next.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) {
      missing = missing || st.st_mode == 0;
      current = next;  // a file, a folder, or nothing (the reader then says it does not exist)
      continue;
    }
    if (++links > kMaxLinks) throw refuse("passes through more than 40 symbolic links");
    std::string target(4096, '\0');
    const ssize_t n = ::readlink(next.c_str(), target.data(), target.size());
    if (n < 0 || std::size_t(n) >= target.size()) throw refuse("has an unreadable symbolic link");
    target.resize(std::size_t(n));
    fs::path t(target);
    if (t.is_absolute()) {
      t = t.lexically_normal();
      if (!inside(t, base))
        throw refuse("leaves the glTF's folder through a symbolic link");
      current = base;
      t = t.lexically_relative(base);
    }
    std::deque<fs::path> expanded;
    for (const fs::path& q : t) expanded.push_back(q);
    todo.insert(todo.begin(), expanded.begin(), expanded.end());
  }
  return current.string();
}

}  // namespace dspbr::gltf
