// Why an implementation fails (docs/conformance.md, "Diagnosis"): the reference evaluated again
// with each classic mistake of a documented vocabulary (a Deviation of the BSDF, another table set,
// a roughness clamp), and for each set of failing vectors the mistakes ranked by how many of the
// failures they explain. A mistake explains a failing vector when the implementation's f cos and
// emission (those it supplied) are within the vector's tolerances of the reference with that
// mistake; it is contradicted by a passing vector whose values the mistake would have moved
// outside them. Ranked by explained minus contradicted, then by the vocabulary's order; a cause
// contradicted as often as it explains is not listed. Vectors whose expectations the reference
// does not reproduce (an edited or stale file) are left out and counted.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dspbr/bsdf/lobe_assembly.h"
#include "dspbr/conformance/checker.h"
#include "dspbr/conformance/demo_tables.h"
#include "dspbr/conformance/vector_set.h"

namespace dspbr::conformance {

// One entry of the vocabulary: a name, the term of the spec it concerns, the pattern that gives it
// away, what to do, and how the reference reproduces it.
struct Cause {
  const char* name;      // "multiple_scattering", ...
  const char* term;      // the spec's term
  const char* evidence;  // where the failures show it
  const char* remedy;    // what to fix (or which option judges it as a representation)
  Deviation deviation = Deviation::None;
  DemoTables tables = DemoTables::Renderer;
  double min_roughness = 0;
};
// The vocabulary, in its documented order (docs/conformance.md, "Diagnosis").
const std::vector<Cause>& causes();

struct CauseScore {
  const Cause* cause = nullptr;
  std::size_t explains = 0;     // failing vectors it explains
  std::size_t contradicts = 0;  // passing vectors it would have failed
};

// The causes of one set of failing vectors (a group, or all of them), best first; only those that
// explain at least one.
struct Ranking {
  std::string group;        // "" for all the vectors
  std::size_t failing = 0;  // vectors whose f cos or emission fails
  std::size_t unreproduced = 0;  // vectors left out: the reference does not give their expectations
  std::vector<CauseScore> causes;
};

struct Diagnosis {
  Ranking overall;
  std::vector<Ranking> groups;  // each group with a failing vector, in the order of first appearance
};

// `results` in the order of `vectors` (match_results), `check` their verdicts; `base` the
// representation the vectors were judged against (expect_with): each cause is applied on top.
Diagnosis diagnose(const std::vector<Vector>& vectors, const std::vector<Result>& results, const Check& check,
                   const Representation& base);

// What the reference reads and computes for one vector, term by term (report.json's `worst`
// entries): each active component's f cos alone ("components", bsdf/material_bsdf.h's
// make_component_bsdf), the table values it read ("tables": E_m(mu_v), E_m(mu_l), E_m,avg;
// B_c's E(mu_v; r, f0), E_avg(r, f0) at f0 = max(F_0 rho_s); the sheen's E_b(mu_v), E_b(mu_l) and
// its layer scaling; the GGX Lambda(v), Lambda(l) and the sheen's), and f cos with each cause of
// the vocabulary ("with_cause"). Angles by |cos| in the core frame as the tables read them.
nlohmann::ordered_json vector_terms(const Vector& x, const Representation& base);
// The companion file of a vector set (`conformance generate`'s terms.json):
// {"format": "dspbr-conformance-terms", "version": 1, "terms": [{"id", "components", "tables",
// "with_cause"}, ...]} in the order of the vectors (vector_terms with the renderer tables).
nlohmann::ordered_json terms_document(const std::vector<Vector>& vectors);

// {"failing", "unreproduced", "causes": [{"cause", "term", "explains", "contradicts", "evidence", "remedy"}]}
nlohmann::ordered_json ranking_json(const Ranking& r);

}  // namespace dspbr::conformance
