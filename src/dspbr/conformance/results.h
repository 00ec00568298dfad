// An implementer's results for a conformance vector set (docs/conformance.md, "Results"):
//   JSON {"results": [{"id": str, "f_cos": [r,g,b], "pdf": number (optional), "albedo": [r,g,b]
//        (optional), "emission": [r,g,b] (optional), "delta": [{"l": [x,y,z], "value": [r,g,b]}]
//        (optional)}]}
//   or CSV with the header id,f_cos_r,f_cos_g,f_cos_b[,pdf][,albedo_r,albedo_g,albedo_b]
// told apart by the first non-blank byte ('{' is JSON). Every problem is a std::runtime_error with
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
  Rgb f_cos;
  std::optional<double> pdf;
  std::optional<Rgb> albedo;
  std::optional<Rgb> emission;
  std::optional<std::vector<DeltaExpectation>> delta;
};

// Reads and parses a results file (size limit limits::kDocumentBytes).
std::vector<Result> read_results(const std::string& path);
// Same from the file's bytes; `path` names it in messages.
std::vector<Result> parse_results(std::string_view bytes, const std::string& path);

// The results in the order of `vectors`. Throws "<path>: no result for vector 'x' (and N more)"
// when a vector has none and "<path>: <record>: id 'x' is not a vector of <vectors_path>" for a
// result of no vector.
std::vector<Result> match_results(const std::vector<Vector>& vectors, std::vector<Result> results,
                                  const std::string& path, const std::string& vectors_path);

}  // namespace dspbr::conformance
