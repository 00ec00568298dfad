// Judging an implementation's results against a conformance vector set (docs/conformance.md,
// "Checking"): each supplied quantity of each vector within its tolerance (per channel
// |result - expected| <= abs + rel |expected|); a vector passes when every quantity judged
// passes; a group (the component a set of vectors tests, "plain_metal", ...) passes when all its
// vectors do. Quantities a results file does not supply are NOT JUDGED; a vector of which no
// quantity is judged is NOT SUPPLIED (neither passes nor fails), and so is a group of such vectors.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dspbr/conformance/results.h"
#include "dspbr/conformance/vector.h"

namespace dspbr::conformance {

// The quantities of a vector, in report order.
enum class Quantity { FCos, Pdf, Albedo, Emission, Delta };
inline constexpr int kQuantities = 5;
const char* quantity_name(Quantity q);  // "f_cos", "pdf", "albedo", "emission", "delta"

// The ratio of a negative value (f cos, pdf, albedo, emission or a delta lobe below 0): it fails
// whatever its tolerance, as a non-finite value from `conformance run` does (1e300).
inline constexpr double kNegativeRatio = 1e300;

// The worst channel's |got - expected| / tolerance.
double rgb_ratio(const Tolerance& t, const Rgb& got, const Rgb& expected);

struct VectorVerdict {
  // Per quantity: the worst channel's error over its tolerance (<= 1 passes); nullopt when the
  // vector has no such expectation or the results do not supply it (NOT JUDGED).
  std::optional<double> ratio[kQuantities];
  bool supplied = false;  // a quantity is judged
  bool passed = false;    // supplied and every judged quantity within its tolerance
  double worst_ratio = 0;  // over the judged quantities
  const char* verdict() const { return !supplied ? "NOT SUPPLIED" : (passed ? "PASS" : "FAIL"); }
};

struct Check {
  std::vector<VectorVerdict> verdicts;  // in the order of the vectors
  std::size_t failed = 0, not_supplied = 0;
  std::size_t judged() const { return verdicts.size() - not_supplied; }
  bool passed() const { return failed == 0; }
};

// The vectors to judge (`dspbr conformance check --groups/--components`): those in one of
// `groups` (all when empty) whose material has one of `components` (all when empty). Throws
// std::invalid_argument naming a group or component no vector has, with the known ones, or when
// no vector is in both.
struct Selection {
  std::vector<std::string> groups, components;
};
void select_vectors(const Selection& s, std::vector<Vector>& vectors, std::vector<Result>& results);

// `results` in the order of `vectors` (match_results).
Check check_results(const std::vector<Vector>& vectors, const std::vector<Result>& results);

// The report document (report.json): overall verdict, per quantity and per group counts
// (judged, passed, failed, not judged), the per-component counts (vectors whose material has the
// component), the `worst` vectors with their materials and directions, and every vector's ratios.
nlohmann::ordered_json check_report(const std::vector<Vector>& vectors, const std::vector<Result>& results,
                                    const Check& check, const nlohmann::ordered_json& provenance, std::size_t worst = 20);

}  // namespace dspbr::conformance
