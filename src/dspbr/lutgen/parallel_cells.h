// Runs the cells of a table in parallel (TBB) on an arena, with progress on stderr.
#pragma once
#include <tbb/task_arena.h>

#include <atomic>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>

namespace dspbr {

// Thrown by parallel_cells once `cancel` is set (Python's Ctrl-C, python/module.cpp): every
// thread stops after the cell it is computing.
struct LutCancelled : std::runtime_error {
  LutCancelled() : std::runtime_error("table generation cancelled") {}
};

// Calls body(i) for i in [0, n), reporting progress as `label` when progress is on and stderr
// is a terminal. Each cell must depend only on its index (results independent of threads).
// `cancel` (may be null) is read before each cell: set, the call throws LutCancelled.
void parallel_cells(tbb::task_arena& arena, size_t n, const std::string& label, bool progress,
                    const std::atomic<bool>* cancel, const std::function<void(size_t)>& body);

}  // namespace dspbr
