// A one-line progress bar on stderr over a parallel loop, redrawn as its indices finish.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace argtool {

// Runs `work(index)` for index in [0, count) on `threads` threads (arg::parallel_for: each
// index once, any order) while drawing "label  done/count [=====     ]" on stderr (plain lines
// in a log). When a call throws, no higher index is started, and the exception of the lowest
// failing index is rethrown here once every thread has finished.
void run_with_progress(const std::string& label, std::size_t count, int threads,
                       const std::function<void(std::size_t)>& work);

}  // namespace argtool
