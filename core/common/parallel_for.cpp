// A loop over [0, n) on several threads: workers with signals blocked, start failures tolerated.
#include "common/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <pthread.h>
#endif

#include "common/signals_blocked.hpp"

namespace arg {

namespace {

// What the threads of one loop share: the next index to hand out and the lowest failure.
class Loop {
 public:
  Loop(std::size_t n, const std::function<void(std::size_t)>& f) : n_(n), f_(f) {}

  // Takes indices until none are left. An index above a failed one is not started: it cannot
  // change which exception is rethrown, and the caller is going to get an error anyway.
  void work() {
    for (std::size_t i = next_++; i < n_ && i < lowest_failed_.load(); i = next_++) {
      try {
        f_(i);
      } catch (...) {
        keep_if_lowest(i, std::current_exception());
      }
    }
  }

  void rethrow_lowest_failure() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  void keep_if_lowest(std::size_t i, std::exception_ptr e) {
    const std::lock_guard<std::mutex> guard(lock_);
    if (i < lowest_failed_.load()) {
      failure_ = std::move(e);
      lowest_failed_ = i;
    }
  }

  const std::size_t n_;
  const std::function<void(std::size_t)>& f_;
  std::atomic<std::size_t> next_{0};
  std::atomic<std::size_t> lowest_failed_{std::numeric_limits<std::size_t>::max()};
  std::mutex lock_;
  std::exception_ptr failure_;
};

// Names the calling thread, where the system lets names be read (Linux: /proc/PID/task/*/comm),
// so that a server's operator, and the cancel test, can tell the workers from other threads.
void name_this_thread(const char* name) {
#if defined(__linux__)
  pthread_setname_np(pthread_self(), name);
#else
  (void)name;
#endif
}

}  // namespace

void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& f,
                  const ThreadStarter& start) {
  if (n == 0) return;
  Loop loop(n, f);
  // The calling thread works too, so it starts at most threads - 1 others, none without work.
  const std::size_t others =
      threads > 1 ? std::min(std::size_t(threads - 1), n - 1) : std::size_t(0);
  std::vector<std::thread> pool;
  pool.reserve(others);  // so that keeping a started thread cannot throw and orphan it
  {
    const SignalsBlocked while_starting;  // new threads inherit this mask, this thread not
    for (std::size_t k = 0; k < others; ++k) {
      std::thread t;
      try {
        t = start([&loop] {
          name_this_thread(kWorkerThreadName);
          loop.work();
        });
      } catch (...) {
        break;  // out of threads or memory: the ones started and this one share the work
      }
      if (!t.joinable()) break;
      pool.push_back(std::move(t));
    }
  }
  loop.work();
  for (std::thread& t : pool) t.join();
  loop.rethrow_lowest_failure();
}

void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& f) {
  parallel_for(n, threads, f,
               [](std::function<void()> body) { return std::thread(std::move(body)); });
}

}  // namespace arg
