// libFuzzer target: the output writer (io/output_folder.h) against an output folder with planted
// links (a file link and a folder link to a folder outside, a sub-folder that is a file). The
// input is a list of lines: the first byte picks commit or discard, each line a relative path
// the run writes into its staging folder. Checked property, beyond "no crash": whatever happens,
// the folder outside holds exactly what it held before, and the staging folder is gone.
#include <stdlib.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dspbr/io/output_folder.h"
#include "temp_folder.h"

namespace fs = std::filesystem;

namespace {

const fs::path& root() {
  static const TempFolder dir("dspbr-fuzz-output");
  return dir.path();
}

std::string listing(const fs::path& dir) {
  std::string out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    std::ifstream in(e.path());
    std::stringstream ss;
    ss << in.rdbuf();
    out += e.path().string() + "=" + ss.str() + "\n";
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || size > 4096) return 0;
  const fs::path outside = root() / "outside", out = root() / "out";
  fs::remove_all(outside);
  fs::remove_all(out);
  fs::create_directories(outside / "folder");
  std::ofstream(outside / "sentinel.json") << "sentinel";
  fs::create_directories(out);
  fs::create_symlink(outside / "sentinel.json", out / "a.json");
  fs::create_directory_symlink(outside / "folder", out / "renderer");
  std::ofstream(out / "file") << "x";
  const std::string before = listing(outside);
  const bool commit = data[0] & 1;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  std::string staging;
  try {
    dspbr::OutputFolder folder(out.string(), "--out");
    staging = folder.staging();
    for (std::string line; std::getline(lines, line);) {
      const fs::path rel(line);
      // The run names its own files: relative, without "..", ".", NUL or empty parts.
      bool ok = !line.empty() && rel.is_relative() && line.find('\0') == std::string::npos;
      for (const fs::path& part : rel) ok = ok && part != ".." && part != "." && !part.empty();
      if (!ok) continue;
      std::error_code ec;
      fs::create_directories((fs::path(staging) / rel).parent_path(), ec);
      if (!ec) std::ofstream(fs::path(staging) / rel) << line;
    }
    if (commit) folder.commit();
  } catch (const std::exception&) {
  }
  if (listing(outside) != before || (!staging.empty() && fs::exists(staging))) {
    std::fprintf(stderr, "the output writer changed a folder outside its output or left its staging folder\n");
    std::abort();
  }
  return 0;
}
