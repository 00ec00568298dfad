// Where a validation report comes from: project version and git commit (fixed when CMake
// configured the build, dspbr/version.h), and the settings of the table file that was used.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace dspbr::validate {

std::string project_version();  // CMake PROJECT_VERSION, e.g. "0.1"
std::string git_describe();     // `git describe --always --dirty` at configure time ("unknown" without git)

// File name, FNV-1a 64-bit hash of its bytes, and the generator settings of each table (sizes,
// integrator, samples, target error, seed) of a `dspbr lut` JSON file, from the file's bytes;
// `name` is what the "file" entry says (the path, or e.g. "built-in luts/dspbr_renderer_luts.json"
// for the tables compiled into the library). Throws std::runtime_error naming it when the bytes
// are not a JSON object.
nlohmann::json table_text_settings(std::string_view bytes, const std::string& name);

// The arguments of this process, program first (/proc/self/cmdline; empty if unknown).
std::vector<std::string> process_arguments();
// The command line of this process (process_arguments joined by spaces; "" if unknown).
std::string process_command_line();

}  // namespace dspbr::validate
