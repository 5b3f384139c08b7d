// A one-line progress bar on stderr over a parallel loop, redrawn as its indices finish.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>

namespace argtool {

// The line of one loop. A terminal gets "label  done/count [=====     ]" redrawn in place at
// most every 0.1 s; a log file gets a plain line at the start, at most one every ten seconds
// and one at the end, with no carriage returns to garble it. With a `unit` ("models") the line
// also gives the rate since the start and the time left at that rate. Any thread may call it.
class ProgressLine {
 public:
  ProgressLine(std::string label, std::size_t count, std::string unit = "");

  // One more index finished. A thread that finds another one drawing goes back to work.
  void advance();
  // Writes `message` on a line of its own above the bar (a file's error, say).
  void note(const std::string& message);
  // Draws the final count (and ends the terminal's line).
  void finish();

 private:
  void draw(std::size_t done);

  const std::string label_, unit_;
  const std::size_t count_;
  const bool tty_;
  const std::chrono::milliseconds period_;
  const std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
  std::atomic<std::size_t> done_{0};
  std::mutex lock_;
};

// Runs `work(index)` for index in [0, count) on `threads` threads (arg::parallel_for: each
// index once, any order) while drawing a ProgressLine without a unit. When a call throws, no
// higher index is started, and the exception of the lowest failing index is rethrown here once
// every thread has finished.
void run_with_progress(const std::string& label, std::size_t count, int threads,
                       const std::function<void(std::size_t)>& work);

}  // namespace argtool
