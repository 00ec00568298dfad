// The project's version, fixed when CMake configures the build (cmake/generated_sources.cmake).
#pragma once

namespace dspbr {

// "<project version> (<git describe --always --dirty>)", e.g. "0.1 (8b5fdf4-dirty)"; the project
// version alone when the build was configured outside a git work tree or without git.
const char* version_string();

// The project version alone (CMake PROJECT_VERSION, e.g. "0.1"): what committed outputs (luts/,
// fits/) record, so that they stay byte-identical from one commit to the next.
const char* project_version();

}  // namespace dspbr
