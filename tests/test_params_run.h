// Runs the built `dspbr` tool (DSPBR_EXE) for end-to-end CLI tests of the params / scene
// commands: exit status and combined stdout+stderr.
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

struct ToolRun {
  int status = -1;  // exit status of the tool
  std::string output;
};

// `cwd`: folder to run in (default: the test's own).
inline ToolRun run_dspbr(const std::string& args, const std::string& cwd = "") {
  ToolRun r;
  const std::string cmd =
      (cwd.empty() ? std::string() : "cd '" + cwd + "' && ") + "\"" + DSPBR_EXE + "\" " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) r.output.append(buf.data(), n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

// Number of lines of `text` containing `needle`.
inline int count_lines_with(const std::string& text, const std::string& needle) {
  int n = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (text.substr(start, end - start).find(needle) != std::string::npos) ++n;
    start = end + 1;
  }
  return n;
}

// A usage error: exit status 2 and one line "dspbr: error: ..." containing `needle` (the output
// shown cut to 2000 characters when the check fails).
inline void expect_usage_error(const std::string& args, const std::string& needle) {
  const ToolRun r = run_dspbr(args);
  const std::string shown = args + "\n" + r.output.substr(0, 2000);
  EXPECT_EQ(r.status, 2) << shown;
  EXPECT_EQ(r.output.rfind("dspbr: error: ", 0), 0u) << shown;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << shown;
  EXPECT_NE(r.output.find(needle), std::string::npos) << shown;
}
