// Where an output of `dspbr` comes from (README, "Provenance"):
//  - documents printed on stdout (eval, sample, scene analyze --json, params list/show --json)
//    carry {"dspbr": version with git describe, "command": the command line} under "provenance";
//  - files meant to be committed (luts/) record the project version alone and the command with the
//    --out folder written DIR and without --threads, so that regenerating them gives the same
//    bytes in any checkout, at any commit and with any thread count.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace dspbr::cli {

// {"dspbr": version_string(), "command": the command line of this process}.
nlohmann::ordered_json output_provenance();

// "dspbr <arguments>" with the value of --out (or --out=...) replaced by DIR and --threads left
// out (the outputs do not depend on it: same seed, same bytes whatever the thread count).
std::string reproducible_command();

}  // namespace dspbr::cli
