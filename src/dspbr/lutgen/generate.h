// The table generator behind `dspbr lut`: the six DSPBR energy-compensation tables (see
// docs/luts.md for definitions, layout and conventions), integrated cell by cell with the
// functions of lutgen/albedo.h, in parallel with TBB. Each cell draws its random numbers from
// (settings.seed, stream = table id * 2^32 + cell index), so the result is bit-identical
// whatever the thread count.
#pragma once
#include <atomic>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dspbr/lutgen/albedo.h"
#include "dspbr/tables/warped_table.h"
#include "dspbr/tables/table.h"
#include "dspbr/tables/table_registry.h"

namespace dspbr {

// The integrator a table uses unless one is chosen (LutOptions::integrator): Quad for every
// table (measured: docs/design/luts.md, "Speed").
Integrator lut_default_integrator(const std::string& table);

// Default maximum samples per cell (all replicates); the averages integrate over one more
// dimension and get more. With the default target error most cells stop far earlier.
int lut_default_samples(const std::string& table);
// Default adaptive target of Qmc and Mc: standard error 1e-5 per cell, a tenth of the 1e-4
// accuracy goal (Quad: kQuadDefaultTolerance, lutgen/albedo.h).
constexpr double kLutDefaultTargetError = 1e-5;
// LutOptions::target_error: "the chosen integrator's default".
constexpr double kLutIntegratorDefault = std::numeric_limits<double>::quiet_NaN();

struct LutOptions {
  std::vector<std::string> tables = lut_table_names();  // which tables (canonical names)
  std::map<std::string, std::vector<int>> sizes;        // per-table sizes (missing: default)
  GridKind grid = GridKind::CellCentred;
  std::optional<Integrator> integrator;  // none: lut_default_integrator(table)
  int samples = 0;         // per cell (maximum when target_error > 0); 0: lut_default_samples(table)
  // Adaptive stop (IntegratorSettings); Qmc/Mc 0: fixed budget; kLutIntegratorDefault (NaN): the
  // integrator's default (kLutDefaultTargetError, Quad kQuadDefaultTolerance).
  double target_error = kLutIntegratorDefault;
  int randomizations = 8;  // replicates per cell (>= 2)
  uint64_t seed = 1;
  int threads = 0;         // 0: all hardware threads
  bool progress = true;    // progress on stderr: a live line on a terminal, a line per table elsewhere
  const std::atomic<bool>* cancel = nullptr;  // set: the generation throws LutCancelled (parallel_cells.h)
  std::string command;     // recorded with project_version() in the files written ("": neither)
};

// The integrator settings used for `table` under `opt`.
IntegratorSettings lut_settings(const std::string& table, const LutOptions& opt);

// The axes of `table` under `opt` (sizes, grid kind; all axes span [0, 1]).
std::vector<Axis> lut_axes(const std::string& table, const LutOptions& opt);

// Checks the options (names, sizes, budgets); throws std::invalid_argument with a one-line
// message saying what to fix.
void validate_lut_options(const LutOptions& opt);

// Generates the requested tables (canonical order). Values and per-cell standard errors.
std::vector<Table> generate_luts(const LutOptions& opt);

}  // namespace dspbr
