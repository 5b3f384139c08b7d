// The progress bar: drawn by whichever worker finishes an index, so it needs no thread of its own.
#include "progress_bar.hpp"

#include <unistd.h>

#include <cstdio>

#include "common/parallel_for.hpp"

namespace argtool {

namespace {

// ", 12.3 models/s, 1:05 left": the rate so far and the time left at that rate (nothing before
// the first index finishes).
std::string rate_text(const std::string& unit, std::size_t done, std::size_t count,
                      double seconds) {
  if (done == 0 || seconds <= 0) return "";
  const double rate = double(done) / seconds;
  const long left = long(double(count - done) / rate + 0.5);
  char text[96];
  if (left >= 3600)
    std::snprintf(text, sizeof text, ", %.1f %s/s, %ld:%02ld:%02ld left", rate, unit.c_str(),
                  left / 3600, left / 60 % 60, left % 60);
  else
    std::snprintf(text, sizeof text, ", %.1f %s/s, %ld:%02ld left", rate, unit.c_str(), left / 60,
                  left % 60);
  return text;
}

}  // namespace

ProgressLine::ProgressLine(std::string label, std::size_t count, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      count_(count),
      tty_(isatty(2) == 1),
      period_(tty_ ? std::chrono::milliseconds(100) : std::chrono::milliseconds(10000)),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {
  draw(0);
}

void ProgressLine::advance() {
  const std::size_t d = ++done_;
  const std::unique_lock<std::mutex> guard(lock_, std::try_to_lock);
  if (!guard.owns_lock()) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < period_) return;
  last_ = now;
  draw(d);
}

void ProgressLine::note(const std::string& message) {
  const std::lock_guard<std::mutex> guard(lock_);
  if (tty_) {
    std::fprintf(stderr, "\r\033[K%s\n", message.c_str());
    draw(done_.load());
  } else {
    std::fprintf(stderr, "%s\n", message.c_str());
  }
}

void ProgressLine::finish() {
  const std::lock_guard<std::mutex> guard(lock_);
  draw(done_.load());
  if (tty_) std::fprintf(stderr, "\n");
}

void ProgressLine::draw(std::size_t d) {
  const std::string rate =
      unit_.empty()
          ? std::string()
          : rate_text(
                unit_, d, count_,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  if (tty_) {
    const int filled = count_ ? int(30 * d / count_) : 30;
    std::fprintf(stderr, "\r%-12s %zu/%zu [%s%s]%s\033[K", label_.c_str(), d, count_,
                 std::string(std::size_t(filled), '=').c_str(),
                 std::string(std::size_t(30 - filled), ' ').c_str(), rate.c_str());
  } else {
    std::fprintf(stderr, "%s %zu/%zu%s\n", label_.c_str(), d, count_, rate.c_str());
  }
}

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
