// Runs the cells of a table in parallel (TBB) on an arena, with progress on stderr.
#pragma once
#include <tbb/task_arena.h>

#include <cstddef>
#include <functional>
#include <string>

namespace dspbr {

// Calls body(i) for i in [0, n), reporting progress as `label` when progress is on and stderr
// is a terminal. Each cell must depend only on its index (results independent of threads).
void parallel_cells(tbb::task_arena& arena, size_t n, const std::string& label, bool progress,
                    const std::function<void(size_t)>& body);

}  // namespace dspbr
