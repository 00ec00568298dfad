// libFuzzer target: the conformance kit's readers (conformance/vector_file.h, results.h): the
// first byte picks a vector document (even) or a results file, JSON or CSV (odd), the rest is
// the file; a results file that parses is matched against the seed vector set.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string_view>
#include <vector>

#include "dspbr/conformance/results.h"
#include "dspbr/conformance/vector_file.h"
#include "dspbr/io/read_file.h"

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
      dspbr::conformance::match_results(seed_vectors, std::move(results), "fuzz.csv", "vectors.json");
    }
  } catch (const std::exception&) {
  }
  return 0;
}
