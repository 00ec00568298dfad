// Where an output of `dspbr` comes from (README, "Provenance"):
//  - documents printed on stdout (eval, sample, scene analyze --json, params list/show --json)
//    carry {"dspbr": version with git describe, "command": the command line} under "provenance";
//  - files meant to be committed (luts/) record the project version alone and the command with the
//    --out folder written DIR, so that regenerating them gives the same bytes in any checkout and
//    at any commit.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace dspbr::cli {

// {"dspbr": version_string(), "command": the command line of this process}.
nlohmann::ordered_json output_provenance();

// "dspbr <arguments>" with the value of --out (or --out=...) replaced by DIR.
std::string reproducible_command();

}  // namespace dspbr::cli
