// Files in tests: read a whole file, write one (creating its folder), list a folder tree.
#pragma once
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

// The whole file, byte for byte ("" when it cannot be read).
inline std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Writes `text` to `path`, creating the missing folders above it.
inline void write(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// Every file and folder below `dir`, as paths relative to it.
inline std::set<std::string> listing(const std::filesystem::path& dir) {
  std::set<std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    out.insert(e.path().lexically_relative(dir).string());
  return out;
}
