#include "dspbr/lutgen/parallel_cells.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dspbr/progress.h"

namespace dspbr {

void parallel_cells(tbb::task_arena& arena, size_t n, const std::string& label, bool progress,
                    const std::atomic<bool>* cancel, const std::function<void(size_t)>& body) {
  Progress report(label, n, progress);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) {
        if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) throw LutCancelled();  // TBB stops the rest
        body(i);
        report.add();
      }
    });
  });
}

}  // namespace dspbr
