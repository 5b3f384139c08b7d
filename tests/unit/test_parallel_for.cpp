// parallel_for: each index once, results independent of the thread count, the lowest failure
// rethrown, workers with signals blocked, and the work done when threads cannot start.
#include <gtest/gtest.h>
#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <mutex>
#include <new>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "common/parallel_for.hpp"

using namespace arg;

namespace {

bool blocks(int signal) {
  sigset_t mask;
  pthread_sigmask(SIG_BLOCK, nullptr, &mask);
  return sigismember(&mask, signal) == 1;
}

// Unblocks SIGINT in the test's thread for a scope, as in a backend that takes query cancels.
class SigintOpen {
 public:
  SigintOpen() {
    sigset_t interrupt;
    sigemptyset(&interrupt);
    sigaddset(&interrupt, SIGINT);
    pthread_sigmask(SIG_UNBLOCK, &interrupt, &saved_);
  }
  ~SigintOpen() { pthread_sigmask(SIG_SETMASK, &saved_, nullptr); }

 private:
  sigset_t saved_;
};

// Which thread ran each index, and how many times it ran.
struct Record {
  explicit Record(std::size_t n) : runs(n), by(n) {}
  std::vector<std::atomic<int>> runs;
  std::vector<std::thread::id> by;
  void ran(std::size_t i) {
    ++runs[i];
    by[i] = std::this_thread::get_id();
  }
  std::set<std::thread::id> threads() const { return {by.begin(), by.end()}; }
};

std::thread failing_start(std::function<void()>) {
  throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again));
}

}  // namespace

TEST(ParallelFor, RunsEveryIndexExactlyOnce) {
  for (int threads : {-1, 0, 1, 2, 3, 8, 16})
    for (std::size_t n : {0, 1, 2, 7, 1000}) {
      Record r(n);
      parallel_for(n, threads, [&](std::size_t i) { r.ran(i); });
      for (std::size_t i = 0; i < n; ++i)
        ASSERT_EQ(r.runs[i], 1) << "index " << i << " of " << n << ", " << threads << " threads";
      EXPECT_LE(r.threads().size(), std::size_t(std::max(threads, 1)));
    }
}

TEST(ParallelFor, ResultsDoNotDependOnTheThreadCount) {
  const std::size_t n = 3000;
  auto results = [&](int threads) {
    std::vector<double> slot(n);
    parallel_for(n, threads, [&](std::size_t i) {
      double x = 0;
      for (std::size_t k = 1; k <= 200 + i % 37; ++k) x += std::sin(double(i * k)) / double(k);
      slot[i] = x;
    });
    return slot;
  };
  const std::vector<double> one = results(1);
  for (int threads = 2; threads <= 8; ++threads) {
    const std::vector<double> other = results(threads);
    EXPECT_EQ(std::memcmp(one.data(), other.data(), n * sizeof(double)), 0) << threads;
  }
}

TEST(ParallelFor, RethrowsTheLowestFailingIndexAfterEveryThreadFinished) {
  for (int threads = 1; threads <= 8; ++threads) {
    const std::size_t n = 400;
    Record r(n);
    std::atomic<int> running{0};
    std::string caught;
    try {
      parallel_for(n, threads, [&](std::size_t i) {
        ++running;
        r.ran(i);
        // Index 37 fails last in time: the rule is by index, not by which failed first.
        if (i == 37) std::this_thread::sleep_for(std::chrono::milliseconds(30));
        --running;
        if (i == 37 || i == 41 || i == 300) throw std::runtime_error(std::to_string(i));
      });
    } catch (const std::runtime_error& e) {
      caught = e.what();
    }
    EXPECT_EQ(caught, "37") << threads << " threads";
    EXPECT_EQ(running, 0) << "a thread still ran after the rethrow";
    for (std::size_t i = 0; i <= 37; ++i) EXPECT_EQ(r.runs[i], 1) << i;
  }
}

TEST(ParallelFor, StartsNoIndexAboveAFailureOnOneThread) {
  Record r(10);
  EXPECT_THROW(parallel_for(10, 1,
                            [&](std::size_t i) {
                              r.ran(i);
                              if (i == 4) throw std::out_of_range("4");
                            }),
               std::out_of_range);
  for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(r.runs[i], i <= 4 ? 1 : 0) << i;
}

TEST(ParallelFor, WorkersStartWithEverySignalBlockedAndTheCallerKeepsItsMask) {
  const SigintOpen open;
  // Every thread parallel_for starts, from its first instruction.
  std::mutex lock;
  std::vector<bool> at_start;
  const ThreadStarter recording = [&](std::function<void()> body) {
    return std::thread([&at_start, &lock, body] {
      {
        const std::lock_guard<std::mutex> guard(lock);
        at_start.push_back(blocks(SIGINT) && blocks(SIGTERM) && blocks(SIGUSR1) && blocks(SIGALRM));
      }
      body();
    });
  };
  parallel_for(
      64, 4, [](std::size_t) {}, recording);
  ASSERT_EQ(at_start.size(), 3u);
  for (bool all_blocked : at_start) EXPECT_TRUE(all_blocked);
  EXPECT_FALSE(blocks(SIGINT));

  // With std::thread, while f runs: index 0 waits until a second thread has begun index 1, so
  // one of them runs outside the caller.
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> entered{0};
  std::vector<std::thread::id> who(2);
  char sigint_blocked[2] = {0, 0};  // not vector<bool>: two threads write it
  parallel_for(2, 2, [&](std::size_t i) {
    who[i] = std::this_thread::get_id();
    sigint_blocked[i] = blocks(SIGINT);
    ++entered;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (entered < 2 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  ASSERT_EQ(entered, 2);
  ASSERT_NE(who[0], who[1]);
  for (std::size_t i = 0; i < 2; ++i)
    EXPECT_EQ(sigint_blocked[i] != 0, who[i] != caller) << "index " << i;
  EXPECT_FALSE(blocks(SIGINT));
}

TEST(ParallelFor, WorkersAreNamedAndTheCallerKeepsItsName) {
  char caller_before[32] = {0}, caller_after[32] = {0};
  pthread_getname_np(pthread_self(), caller_before, sizeof caller_before);
  std::mutex lock;
  std::set<std::string> worker_names;
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> entered{0};
  parallel_for(2, 2, [&](std::size_t) {
    ++entered;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (entered < 2 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (std::this_thread::get_id() == caller) return;
    char name[32] = {0};
    pthread_getname_np(pthread_self(), name, sizeof name);
    const std::lock_guard<std::mutex> guard(lock);
    worker_names.insert(name);
  });
  EXPECT_EQ(worker_names, std::set<std::string>{kWorkerThreadName});
  pthread_getname_np(pthread_self(), caller_after, sizeof caller_after);
  EXPECT_STREQ(caller_after, caller_before);
}

TEST(ParallelFor, DoesTheWorkOnTheCallingThreadWhenNoThreadStarts) {
  const std::size_t n = 200;
  Record r(n);
  parallel_for(
      n, 8, [&](std::size_t i) { r.ran(i); }, failing_start);
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(r.runs[i], 1) << i;
  EXPECT_EQ(r.threads(), std::set<std::thread::id>{std::this_thread::get_id()});

  const ThreadStarter out_of_memory = [](std::function<void()>) -> std::thread {
    throw std::bad_alloc();
  };
  Record m(n);
  parallel_for(
      n, 4, [&](std::size_t i) { m.ran(i); }, out_of_memory);
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(m.runs[i], 1) << i;
}

TEST(ParallelFor, SharesTheWorkAmongTheThreadsThatDidStart) {
  const std::size_t n = 500;
  Record r(n);
  int calls = 0;
  const ThreadStarter second_fails = [&](std::function<void()> body) {
    if (++calls > 1) return failing_start(body);
    return std::thread(std::move(body));
  };
  parallel_for(
      n, 6,
      [&](std::size_t i) {
        r.ran(i);
        std::this_thread::sleep_for(std::chrono::microseconds(50));
      },
      second_fails);
  EXPECT_EQ(calls, 2);  // no further attempt after a failure
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(r.runs[i], 1) << i;
  EXPECT_LE(r.threads().size(), 2u);

  // A failure to start and a failing index together: the exception still comes back.
  EXPECT_THROW(parallel_for(
                   n, 3,
                   [](std::size_t i) {
                     if (i == 9) throw std::logic_error("9");
                   },
                   failing_start),
               std::logic_error);
}
