// A one-line progress bar on stderr, redrawn while worker threads advance a counter.
#pragma once

#include <unistd.h>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace argtool {

// Runs `work(index)` for index in [0, count) on `threads` threads (each index once, any
// order) while drawing "label  done/count [=====     ]" on stderr (plain lines in a log).
// When a call throws, no further index is started and the first exception is rethrown here
// once every thread has finished.
template <class Work>
void run_with_progress(const std::string& label, std::size_t count, int threads, Work&& work) {
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> finished{false};
  std::mutex failure_lock;
  std::exception_ptr failure;
  auto worker = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        work(i);
      } catch (...) {
        const std::lock_guard<std::mutex> guard(failure_lock);
        if (!failure) failure = std::current_exception();
        next = count;  // the others stop at their next index
      }
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  std::thread drawer([&] {
    // A terminal gets a bar redrawn in place; a log file gets a plain line every ten seconds
    // and one at the end, with no carriage returns to garble it.
    const bool tty = isatty(2);
    const auto period = std::chrono::milliseconds(tty ? 100 : 10000);
    const auto tick = std::chrono::milliseconds(100);
    auto last = std::chrono::steady_clock::now() - period;
    while (true) {
      const bool last_frame = finished.load();
      const std::size_t d = done.load();
      const auto now = std::chrono::steady_clock::now();
      if (last_frame || now - last >= period) {
        last = now;
        if (tty) {
          const int filled = count ? int(30 * d / count) : 30;
          std::fprintf(stderr, "\r%-12s %zu/%zu [%s%s]", label.c_str(), d, count,
                       std::string(std::size_t(filled), '=').c_str(),
                       std::string(std::size_t(30 - filled), ' ').c_str());
        } else {
          std::fprintf(stderr, "%s %zu/%zu\n", label.c_str(), d, count);
        }
      }
      if (last_frame) break;
      std::this_thread::sleep_for(tick);
    }
    if (tty) std::fprintf(stderr, "\n");
  });
  worker();
  for (auto& t : pool) t.join();
  finished = true;
  drawer.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace argtool
