// The progress bar: drawn by whichever worker finishes an index, so it needs no thread of its own.
#include "progress_bar.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>

#include "common/parallel_for.hpp"

namespace argtool {

namespace {

// The line of one loop. A terminal gets a bar redrawn in place at most every 0.1 s; a log file
// gets a plain line at the start, at most one every ten seconds and one at the end, with no
// carriage returns to garble it.
class ProgressLine {
 public:
  ProgressLine(const std::string& label, std::size_t count)
      : label_(label),
        count_(count),
        tty_(isatty(2) == 1),
        period_(tty_ ? std::chrono::milliseconds(100) : std::chrono::milliseconds(10000)),
        last_(std::chrono::steady_clock::now()) {
    draw(0);
  }

  // One more index finished. A thread that finds another one drawing goes back to work.
  void advance() {
    const std::size_t d = ++done_;
    const std::unique_lock<std::mutex> guard(lock_, std::try_to_lock);
    if (!guard.owns_lock()) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < period_) return;
    last_ = now;
    draw(d);
  }

  void finish() {
    const std::lock_guard<std::mutex> guard(lock_);
    draw(done_.load());
    if (tty_) std::fprintf(stderr, "\n");
  }

 private:
  void draw(std::size_t d) const {
    if (tty_) {
      const int filled = count_ ? int(30 * d / count_) : 30;
      std::fprintf(stderr, "\r%-12s %zu/%zu [%s%s]", label_.c_str(), d, count_,
                   std::string(std::size_t(filled), '=').c_str(),
                   std::string(std::size_t(30 - filled), ' ').c_str());
    } else {
      std::fprintf(stderr, "%s %zu/%zu\n", label_.c_str(), d, count_);
    }
  }

  const std::string label_;
  const std::size_t count_;
  const bool tty_;
  const std::chrono::milliseconds period_;
  std::chrono::steady_clock::time_point last_;
  std::atomic<std::size_t> done_{0};
  std::mutex lock_;
};

}  // namespace

void run_with_progress(const std::string& label, std::size_t count, int threads,
                       const std::function<void(std::size_t)>& work) {
  ProgressLine line(label, count);
  try {
    arg::parallel_for(count, threads, [&](std::size_t i) {
      try {
        work(i);
      } catch (...) {
        line.advance();
        throw;
      }
      line.advance();
    });
  } catch (...) {
    line.finish();
    throw;
  }
  line.finish();
}

}  // namespace argtool
