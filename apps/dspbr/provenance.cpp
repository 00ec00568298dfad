#include "provenance.h"

#include <vector>

#include "dspbr/validate/provenance.h"
#include "dspbr/version.h"

namespace dspbr::cli {

nlohmann::ordered_json output_provenance() {
  return {{"dspbr", version_string()}, {"command", validate::process_command_line()}};
}

std::string reproducible_command() {
  const std::vector<std::string> args = validate::process_arguments();
  std::string out = "dspbr";
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i].rfind("--threads=", 0) == 0) continue;
    if (args[i] == "--threads") {
      ++i;  // and its value
      continue;
    }
    if (args[i].rfind("--out=", 0) == 0) {
      out += " --out=DIR";
      continue;
    }
    out += " " + args[i];
    if (args[i] == "--out" && i + 1 < args.size()) out += " DIR", ++i;
  }
  return out;
}

}  // namespace dspbr::cli
