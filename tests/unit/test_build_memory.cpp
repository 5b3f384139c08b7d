// The build's memory cap: the estimate bounds measured builds and grows with the input, a build
// over it is refused before it allocates, and one whose heap grows past it is stopped.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>
#include <thread>

#include "common/errors.hpp"
#include "common/heap_usage.hpp"
#include "io/write_mesh.hpp"
#include "pipeline/build_arg.hpp"
#include "pipeline/build_memory.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

constexpr std::size_t kMB = std::size_t(1) << 20;

TEST(BuildMemory, EstimateGrowsWithEveryCountAndOption) {
  const BuildOptions base;
  std::size_t last = 0;
  for (std::size_t t : {0, 1000, 100000, 1000000, 8000000}) {
    const std::size_t bytes = estimate_build_bytes(t / 2, t, base);
    EXPECT_GE(bytes, last) << t << " triangles";
    last = bytes;
  }
  last = 0;
  for (std::size_t v : {0, 1000, 100000, 4000000}) {
    const std::size_t bytes = estimate_build_bytes(v, 200000, base);
    EXPECT_GE(bytes, last) << v << " vertices";
    last = bytes;
  }
  BuildOptions more = base;
  for (int threads : {2, 8, 64}) {
    more.threads = threads;
    EXPECT_GE(estimate_build_bytes(100000, 200000, more),
              estimate_build_bytes(100000, 200000, base))
        << threads << " threads";
  }
  more = base;
  more.levels = kMaxLevels;
  EXPECT_GE(estimate_build_bytes(100000, 200000, more), estimate_build_bytes(100000, 200000, base));
  more = base;
  more.proxy_resolution = kMaxProxyResolution;
  EXPECT_GT(estimate_build_bytes(1000, 2000, more), estimate_build_bytes(1000, 2000, base));
  more = base;
  more.surface = SurfaceKind::Mesh;  // auto may take the proxy; mesh never does
  EXPECT_LE(estimate_build_bytes(1000, 2000, more), estimate_build_bytes(1000, 2000, base));
  // Counts no reader accepts still give a number, not a wrapped one.
  EXPECT_GE(estimate_build_bytes(std::size_t(1) << 40, std::size_t(1) << 41, base), std::size_t(1)
                                                                                        << 40);
}

// The heap's peak above its level at the start, as the polls of a build see it.
std::size_t polled_peak(const std::string& bytes, const BuildOptions& options) {
  const std::size_t start = heap_bytes_in_use();
  std::size_t peak = 0;
  const StopRequested stop = [&] {
    const std::size_t now = heap_bytes_in_use();
    peak = std::max(peak, now > start ? now - start : 0);
    return false;
  };
  Limits limits;
  limits.max_build_bytes = 0;
  build_arg_bytes(bytes, {}, options, limits, stop);
  return peak;
}

TEST(BuildMemory, EstimateBoundsAMeasuredBuild) {
  if (!heap_tracking_available()) GTEST_SKIP() << "no heap tracking in this build";
  const Mesh torus = test::torus(2, 0.6, 400, 125);  // 100,000 triangles
  const std::string ply = write_ply_binary(torus);
  for (int threads : {1, 2}) {
    BuildOptions options;
    options.threads = threads;
    options.surface = SurfaceKind::Mesh;  // closed: auto would not take the proxy either
    const std::size_t peak = polled_peak(ply, options);
    const std::size_t estimate =
        estimate_build_bytes(std::size_t(torus.V.rows()), std::size_t(torus.F.rows()), options);
    EXPECT_GT(peak, 10 * kMB) << "the polls should see the build's own allocations";
    EXPECT_GE(estimate, peak) << threads << " threads: peak " << peak / kMB << " MB";
  }
}

TEST(BuildMemory, ABuildOverTheCapIsRefusedFromItsCounts) {
  const Mesh torus = test::torus(2, 0.6, 400, 125);
  const std::string ply = write_ply_binary(torus);
  const std::size_t estimate =
      estimate_build_bytes(std::size_t(torus.V.rows()), std::size_t(torus.F.rows()), {});
  Limits limits;
  limits.max_build_bytes = estimate - 1;
  int polls = 0;
  const StopRequested count = [&] {
    ++polls;
    return false;
  };
  try {
    build_arg_bytes(ply, {}, {}, limits, count);
    FAIL() << "a build over the cap ran";
  } catch (const MemoryLimitError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("needs an estimated " + std::to_string(megabytes(estimate)) + " MB"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("cap of " + std::to_string(megabytes(limits.max_build_bytes))),
              std::string::npos)
        << message;
  }
  // Refused from the PLY header's counts: not even the reader polled, where reading the same
  // bytes polls.
  EXPECT_EQ(polls, 0);
  int read_polls = 0;
  const StopRequested count_read = [&] {
    ++read_polls;
    return false;
  };
  ReadOptions read;
  read.stop = count_read;
  read_mesh(ply, read);
  EXPECT_GT(read_polls, 0);
  limits.max_build_bytes = estimate;
  EXPECT_NO_THROW(build_arg_bytes(ply, {}, {}, limits));
}

TEST(BuildMemory, TheHookStopsOnceTheHeapGrowsPastTheCap) {
  if (!heap_tracking_available()) GTEST_SKIP() << "no heap tracking in this build";
  bool asked = false;
  const StopRequested inner = [&] {
    asked = true;
    return false;
  };
  const StopRequested hook = bounded_by_heap(inner, 32 * kMB);
  EXPECT_FALSE(hook());
  EXPECT_TRUE(asked);
  std::unique_ptr<char[]> block(new char[64 * kMB]);
  std::memset(block.get(), 1, 64 * kMB);
  EXPECT_THROW(hook(), MemoryLimitError);
  block.reset();
  EXPECT_FALSE(hook());  // freed: back under the cap
  // The inner stop still wins.
  EXPECT_TRUE(bounded_by_heap([] { return true; }, 32 * kMB)());
  // No cap: the hook is the inner one.
  EXPECT_FALSE(bounded_by_heap({}, 0));
}

TEST(BuildMemory, AReadingOfTheHeapWaitsTwentyTimesWhatItCost) {
  using std::chrono::microseconds;
  using std::chrono::milliseconds;
  EXPECT_EQ(heap_check_wait(microseconds(3)), microseconds(60));
  EXPECT_EQ(heap_check_wait(milliseconds(2)), milliseconds(40));
  EXPECT_EQ(heap_check_wait(milliseconds(10)), milliseconds(50));  // at most 50 ms
  EXPECT_EQ(heap_check_wait(std::chrono::nanoseconds(0)), std::chrono::nanoseconds(0));
}

TEST(BuildMemory, TheHookReadsTheHeapOnlyAfterItsWait) {
  if (!heap_tracking_available()) GTEST_SKIP() << "no heap tracking in this build";
  const StopRequested hook = bounded_by_heap({}, 32 * kMB);
  // Readings follow one another closely here: most polls fall inside a wait and read nothing,
  // so a million polls cost far less than a million readings would.
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 1000000; ++i) ASSERT_FALSE(hook());
  const auto polls = std::chrono::steady_clock::now() - start;
  const auto reading_start = std::chrono::steady_clock::now();
  for (int i = 0; i < 1000; ++i) (void)heap_bytes_in_use();
  const auto per_reading = (std::chrono::steady_clock::now() - reading_start) / 1000;
  EXPECT_LT(polls, 1000000 * per_reading / 4);
}

TEST(BuildMemory, HooksShareTheProcesssReadings) {
  if (!heap_tracking_available()) GTEST_SKIP() << "no heap tracking in this build";
  const StopRequested first = bounded_by_heap({}, 32 * kMB);
  const StopRequested second = bounded_by_heap({}, 32 * kMB);
  std::unique_ptr<char[]> block(new char[64 * kMB]);
  std::memset(block.get(), 1, 64 * kMB);
  std::this_thread::sleep_for(std::chrono::milliseconds(60));  // past any wait
  EXPECT_THROW(first(), MemoryLimitError);
  // Stopped too, by the first one's reading or, if one is due already, by its own.
  EXPECT_THROW(second(), MemoryLimitError);
}

TEST(BuildMemory, AHookMeasuresFromItsOwnStart) {
  if (!heap_tracking_available()) GTEST_SKIP() << "no heap tracking in this build";
  std::unique_ptr<char[]> block(new char[64 * kMB]);
  std::memset(block.get(), 1, 64 * kMB);
  const StopRequested before_free = bounded_by_heap({}, 32 * kMB);
  block.reset();
  // Made after the free: the process's readings from before it (64 MB higher) are not its level.
  const StopRequested after_free = bounded_by_heap({}, 32 * kMB);
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  EXPECT_FALSE(before_free());
  EXPECT_FALSE(after_free());
  block.reset(new char[64 * kMB]);
  std::memset(block.get(), 1, 64 * kMB);
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  EXPECT_THROW(after_free(), MemoryLimitError);
  // The first hook's level held the block: the new one is no growth past its cap.
  EXPECT_FALSE(before_free());
}

TEST(BuildMemory, ABuildWhoseHeapPassesTheCapIsStopped) {
  if (!heap_tracking_available()) GTEST_SKIP() << "no heap tracking in this build";
  const Mesh torus = test::torus(2, 0.6, 400, 125);
  // Past the estimate's check (build_arg takes a mesh), so only the tracking can stop it.
  try {
    build_arg(torus, {}, bounded_by_heap({}, 4 * kMB));
    FAIL() << "a build of 100,000 triangles stayed under 4 MB";
  } catch (const MemoryLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the build memory cap of 4 MB"),
              std::string::npos)
        << e.what();
  }
  // And the process goes on: the same build without the cap completes.
  EXPECT_NO_THROW(build_arg(torus, {}, bounded_by_heap({}, 0)));
}

TEST(BuildMemory, TheCapNeverChangesTheValue) {
  const Mesh torus = test::torus(2, 0.6, 200, 60);
  const std::string ply = write_ply_binary(torus);
  Limits none;
  none.max_build_bytes = 0;
  EXPECT_EQ(build_arg_bytes(ply, {}, {}, Limits{}), build_arg_bytes(ply, {}, {}, none));
}

}  // namespace
