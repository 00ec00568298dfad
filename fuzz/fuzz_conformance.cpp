// libFuzzer target: the conformance kit's readers (conformance/vector_file.h, results.h) and its
// report phase (checker.h): the first byte picks a vector document (even) or a results file, JSON
// or CSV (odd), the rest is the file. A results file that parses is matched against the seed
// vector set, judged, and its report built and serialised as `conformance check` writes
// report.json; the target aborts when that report cannot be written (json_text refuses a
// non-finite number) or does not read back with the verdict of the check.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string_view>
#include <vector>

#include "dspbr/conformance/checker.h"
#include "dspbr/conformance/results.h"
#include "dspbr/conformance/vector_file.h"
#include "dspbr/io/json_write.h"
#include "dspbr/io/read_file.h"

namespace {

// What `conformance check` does with matched results (apps/dspbr/conformance_judge.cpp), without
// the files: judge, build the report, serialise it; the text must read back.
void report_phase(const std::vector<dspbr::conformance::Vector>& vectors,
                  const std::vector<dspbr::conformance::Result>& results) {
  const dspbr::conformance::Check check = dspbr::conformance::check_results(vectors, results);
  const nlohmann::ordered_json report = dspbr::conformance::check_report(vectors, results, check, {});
  std::string text;
  try {
    text = dspbr::json_text(report, 1, "report.json");
  } catch (const std::exception&) {
    std::abort();  // a report of legal results that cannot be written
  }
  const nlohmann::json back = nlohmann::json::parse(text);
  if (!back.contains("verdict") || back["verdict"] != (check.passed() ? "PASS" : "FAIL")) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  static const std::vector<dspbr::conformance::Vector> seed_vectors = [] {
    try {
      return dspbr::conformance::read_vectors(DSPBR_FUZZ_VECTORS);
    } catch (const std::exception&) {
      std::abort();  // the committed seed must read
    }
  }();
  try {
    if (data[0] % 2 == 0) {
      const nlohmann::json doc = dspbr::parse_json(text, "fuzz.json", "conformance vector file");
      dspbr::conformance::vectors_from_json(doc, "fuzz.json");
    } else {
      auto results = dspbr::conformance::parse_results(text, "fuzz.csv");
      results = dspbr::conformance::match_results(seed_vectors, std::move(results), "fuzz.csv", "vectors.json");
      report_phase(seed_vectors, results);
    }
  } catch (const std::exception&) {
  }
  return 0;
}
