// The project's version, fixed when CMake configures the build (cmake/generated_sources.cmake).
#pragma once

namespace dspbr {

// "<project version> (<git describe --always --dirty>)", e.g. "0.1 (8b5fdf4-dirty)"; the project
// version alone when the build was configured outside a git work tree or without git.
const char* version_string();

}  // namespace dspbr
