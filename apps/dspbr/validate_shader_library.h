// The shader library's C++ compile in `dspbr validate` (report section "The shader library";
// docs/validation.md): the reference catalog's whole-material cases and stability corners rebuilt
// on shader::ShaderBsdf, checked by the same furnace, chi-square and stability checks, and its
// conformance over the default vector set of `dspbr conformance generate` (quick: its built-in
// materials' part), one verdict per group.
#pragma once
#include "dspbr/validate/catalog.h"
#include "dspbr/validate/suite.h"

namespace dspbr::cli {

validate::OtherImplementation shader_library_checks(const validate::Catalog& reference, bool quick);

}  // namespace dspbr::cli
