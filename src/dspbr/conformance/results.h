// An implementer's results for a conformance vector set (docs/conformance.md, "Results"):
//   JSON {"results": [{"id": str, "f_cos": [r,g,b], "pdf": number, "albedo": [r,g,b],
//        "emission": [r,g,b], "delta": [{"l": [x,y,z], "value": [r,g,b]}]}]}
//   or CSV with the header id,f_cos_r,f_cos_g,f_cos_b[,pdf][,albedo_r,albedo_g,albedo_b]
// told apart by the first non-blank byte ('{' or '[' is JSON). Every quantity may be not supplied: a JSON
// member left out or null, CSV fields left empty (all three of a colour); a vector may have no
// result at all. What is not supplied is not judged (checker.h). Every problem is a std::runtime_error with
// one line naming the file and the record: "<path>: results[3] (id 'x'): f_cos[1] must be a finite
// number, got null", "<path>: line 7 (id 'x'): pdf is not a finite number: 'nan'", missing and
// unknown ids, duplicates, wrong shapes.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dspbr/conformance/vector.h"

namespace dspbr::conformance {

struct Result {
  std::string id;
  std::optional<Rgb> f_cos;
  std::optional<double> pdf;
  std::optional<Rgb> albedo;
  std::optional<Rgb> emission;
  std::optional<std::vector<DeltaExpectation>> delta;
};

// The results document ({"results": [...]}, the JSON form above) of `results`: each quantity
// supplied, in the order id, f_cos, pdf, albedo, emission, delta; a result with nothing supplied
// is left out.
nlohmann::ordered_json results_document(const std::vector<Result>& results);

// Reads and parses a results file (size limit limits::kDocumentBytes).
std::vector<Result> read_results(const std::string& path);
// Same from the file's bytes; `path` names it in messages.
std::vector<Result> parse_results(std::string_view bytes, const std::string& path);

// --require-all: throws "<path>: no result with an f_cos for vector 'x' (and N more): every vector
// of <vectors_path> needs one (--require-all)" unless results[i] (matched to vectors[i]) has its f cos.
void require_f_cos(const std::vector<Vector>& vectors, const std::vector<Result>& results, const std::string& path,
                   const std::string& vectors_path);

// The results in the order of `vectors`; a vector without one gets a Result that supplies
// nothing. Throws "<path>: <record>: id 'x' is not a vector of <vectors_path>" for a result of no
// vector, and with `require_all` what require_f_cos throws.
std::vector<Result> match_results(const std::vector<Vector>& vectors, std::vector<Result> results,
                                  const std::string& path, const std::string& vectors_path, bool require_all = false);

}  // namespace dspbr::conformance
