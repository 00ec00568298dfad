// Compiled by the parent project of tests/add_subdirectory: the library's headers are found
// through dspbr::dspbr.
#include "dspbr/limits.h"
#include "dspbr/material.h"
#include "dspbr/version.h"

static_assert(dspbr::limits::kJsonDepth > 0, "limits.h is the project's");

const char* parent_version() { return dspbr::version_string(); }
