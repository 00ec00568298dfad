// Conventions of the `dspbr` command as a whole (apps/dspbr/main.cpp): --version, exit codes
// (0 success, 1 checks failed, 2 bad input or usage), one-line errors naming the file.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "dspbr/version.h"
#include "test_params_run.h"

TEST(Cli, VersionPrintsProjectVersionAndGitDescription) {
  const ToolRun r = run_dspbr("--version");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, std::string("dspbr ") + dspbr::version_string() + "\n");
  // "<version>" or "<version> (<describe>)": an abbreviated hash, optionally after a tag and
  // before "-dirty".
  const std::regex form("dspbr " + std::regex_replace(DSPBR_PROJECT_VERSION, std::regex("\\."), "\\.") +
                        "( \\(([^ ]+-g)?[0-9a-f]{4,40}(-dirty)?\\))?\n");
  EXPECT_TRUE(std::regex_match(r.output, form)) << r.output;
}
