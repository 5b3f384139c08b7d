// Cancelling a build at any moment: how long it runs between polls, and how soon a stop ends it.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

#include "common/errors.hpp"
#include "io/write_mesh.hpp"
#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

// CPU time of the calling thread: a build with threads=1 does all its work there, and unlike the
// wall clock it does not count the time other processes of a busy machine take the core.
double thread_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// A torus as binary PLY, its vertices and faces in a shuffled order like a scan's (sorted input
// would flatter the sorts).
std::string shuffled_torus_ply(int rows, int cols) {
  const Mesh grid = test::torus(2, 0.6, rows, cols);
  std::mt19937 rng(7);
  std::vector<int> vertex(std::size_t(grid.V.rows())), face(std::size_t(grid.F.rows()));
  std::iota(vertex.begin(), vertex.end(), 0);
  std::iota(face.begin(), face.end(), 0);
  std::shuffle(vertex.begin(), vertex.end(), rng);
  std::shuffle(face.begin(), face.end(), rng);
  Mesh m;
  m.V.resize(grid.V.rows(), 3);
  m.F.resize(grid.F.rows(), 3);
  for (Eigen::Index v = 0; v < grid.V.rows(); ++v) m.V.row(vertex[std::size_t(v)]) = grid.V.row(v);
  for (Eigen::Index f = 0; f < grid.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) m.F(face[std::size_t(f)], c) = vertex[std::size_t(grid.F(f, c))];
  return write_ply_binary(m);
}

// 200,000 triangles: a tenth of the 2-million-triangle mesh of bench/bench_cancel.cpp and of
// the on-demand test below; the loops that poll grow with the faces, so gaps scale by about ten.
const std::string& large_ply() {
  static const std::string bytes = shuffled_torus_ply(400, 250);
  return bytes;
}

struct PollRecord {
  double total_ms = 0;     // the whole build
  double largest_gap = 0;  // between consecutive polls (and the start and end)
  double gap_at = 0;       // where the largest gap began
};

// One build that records the time of every poll and never stops.
const PollRecord& recorded_build() {
  static const PollRecord record = [] {
    PollRecord r;
    const std::string& ply = large_ply();  // made before the clock starts
    const double start = thread_ms();
    double last = start;
    auto note = [&](double now) {
      if (now - last > r.largest_gap) r.largest_gap = now - last, r.gap_at = last - start;
      last = now;
    };
    const StopRequested stop = [&] {
      note(thread_ms());
      return false;
    };
    build_arg_bytes(ply, {}, BuildOptions{}, Limits{}, stop);
    note(thread_ms());
    r.total_ms = last - start;
    return r;
  }();
  return record;
}

// The target is a cancel within 200 ms on 5 million triangles (1 s at most): 8 ms would be the
// share of this mesh, but what remains between polls is single passes over memory and the
// freeing of buffers, noisy on a shared machine. The build measures 22 ms here (317 ms before
// the loops polled), and 60 ms holds 2 million triangles under 600 ms.
constexpr double kGapLimitMs = 60;

TEST(BuildCancel, PollsTheStopCallbackThroughoutTheBuild) {
#ifdef ARG_SANITIZED
  // Ten times slower under the sanitizers: a minute of make test for timings the release
  // build checks; the unwinding from a stop is exercised there by the mu and proxy tests.
  GTEST_SKIP() << "timings are checked in the release build";
#endif
  const PollRecord& r = recorded_build();
  EXPECT_LT(r.largest_gap, kGapLimitMs) << "largest gap between polls began " << r.gap_at
                                        << " ms into a build of " << r.total_ms << " ms (CPU time)";
}

TEST(BuildCancel, AStopAtAnyMomentEndsTheBuildSoon) {
#ifdef ARG_SANITIZED
  // Ten times slower under the sanitizers: a minute of make test for timings the release
  // build checks; the unwinding from a stop is exercised there by the mu and proxy tests.
  GTEST_SKIP() << "timings are checked in the release build";
#endif
  // The moments are shares of the polls of a build just before, not of its CPU time: with
  // threads=1 a build polls the same number of times every run, while its CPU time varies by
  // a fifth or more with what ran before it in the process (the heap it finds) and with the
  // machine's load, so a moment in time could fall after a second build had already ended.
  const std::string& ply = large_ply();
  long polls = 0;
  build_arg_bytes(ply, {}, BuildOptions{}, Limits{}, [&] {
    ++polls;
    return false;
  });
  ASSERT_GT(polls, 100);
  for (double share : {0.03, 0.2, 0.45, 0.65, 0.8, 0.97}) {
    const long moment = long(share * double(polls));
    long seen = 0;
    double asked = 0;
    const StopRequested stop = [&] {
      if (seen++ < moment) return false;
      if (asked == 0) asked = thread_ms();
      return true;
    };
    EXPECT_THROW(build_arg_bytes(ply, {}, BuildOptions{}, Limits{}, stop), Interrupted)
        << "at " << share * 100 << "% of the polls";
    ASSERT_GT(asked, 0.0);
    // From the first poll told to stop to the end of the unwinding; the gaps before that poll
    // are PollsTheStopCallbackThroughoutTheBuild's to check.
    EXPECT_LT(thread_ms() - asked, kGapLimitMs) << "at " << share * 100 << "% of the polls";
  }
}

// CPU ms from the poll at index `at` (told to stop) to the end of the unwinding of a real build.
double real_stop_ms(const std::string& ply, const Limits& limits, long at) {
  long seen = 0;
  double asked = 0;
  try {
    build_arg_bytes(ply, {}, BuildOptions{}, limits, [&] {
      if (seen++ < at) return false;
      if (asked == 0) asked = thread_ms();
      return true;
    });
  } catch (const Interrupted&) {
    return thread_ms() - asked;
  }
  return -1;  // it did not stop
}

// The issue's own check, on demand (`make cancel-check`: two to three builds of 2,000,000
// triangles, minutes of CPU, too long for make test's hour, which checks the tenth-size mesh
// above). A first build counts its polls; the second forks at 20 of them, the middle of each
// twentieth: the child is told to stop and reports the CPU time from the fork to the end of its
// unwinding (a forked child's clocks start at zero), the parent waits for it and goes on. One
// build so stops at 20 moments, where 20 real stops would cost about ten. A child's time is an
// upper bound: the heap it frees is shared with the parent, so each page it writes is copied
// first (1.05 s in a child against 0.22 s in a real stop, late in the build, where millions of
// small blocks are freed); a moment over the bound in a child is stopped again for real.
TEST(BuildCancel, DISABLED_TwentyStopsOfATwoMillionTriangleBuild) {
  const std::string ply = shuffled_torus_ply(1000, 1000);
  Limits limits;
  limits.max_build_bytes = 0;  // its estimate (1.2 GB) is over the default cap
  long polls = 0;
  build_arg_bytes(ply, {}, BuildOptions{}, limits, [&] {
    ++polls;
    return false;
  });
  ASSERT_GT(polls, 1000);
  constexpr int kMoments = 20;
  std::vector<double> stop_ms;
  long seen = 0;
  int child_pipe = -1;  // the write end of its pipe, in a child only
  const StopRequested stop = [&] {
    const int next = int(stop_ms.size());
    if (next >= kMoments || seen++ != polls * (2 * next + 1) / (2 * kMoments)) return false;
    int fds[2];
    if (pipe(fds) != 0) {
      stop_ms.push_back(-1);
      return false;
    }
    std::fflush(nullptr);
    const pid_t child = fork();
    if (child == 0) {
      close(fds[0]);
      child_pipe = fds[1];
      return true;
    }
    close(fds[1]);
    double ms = -1;
    if (child > 0) {
      if (read(fds[0], &ms, sizeof ms) != ssize_t(sizeof ms)) ms = -1;
      int status = 0;
      waitpid(child, &status, 0);
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) ms = -1;
    }
    close(fds[0]);
    stop_ms.push_back(ms);
    return false;
  };
  try {
    build_arg_bytes(ply, {}, BuildOptions{}, limits, stop);
  } catch (const Interrupted&) {
    // A child: report and leave at once, running nothing more of the test program.
    if (child_pipe < 0) throw;
    const double ms = thread_ms();
    _exit(write(child_pipe, &ms, sizeof ms) == ssize_t(sizeof ms) ? 0 : 1);
  } catch (...) {
    if (child_pipe >= 0) _exit(2);
    throw;
  }
  if (child_pipe >= 0) _exit(3);  // a child whose build did not stop
  ASSERT_EQ(stop_ms.size(), std::size_t(kMoments));
  std::vector<double> sorted = stop_ms;
  std::sort(sorted.begin(), sorted.end());
  std::printf(
      "%ld polls; CPU ms from the stop to the end of the unwinding, median %.1f, max %.1f\n", polls,
      sorted[kMoments / 2], sorted.back());
  for (int i = 0; i < kMoments; ++i) {
    const double forked = stop_ms[std::size_t(i)];
    EXPECT_GE(forked, 0.0) << "moment " << i << ": the child failed";
    // The bound: 1 s at every moment (aim 200 ms).
    if (forked < 1000.0) continue;
    const double real = real_stop_ms(ply, limits, polls * (2 * i + 1) / (2 * kMoments));
    std::printf("moment %d: %.1f ms in a child, %.1f ms in a real stop\n", i, forked, real);
    EXPECT_GE(real, 0.0) << "moment " << i << ": the build did not stop";
    EXPECT_LT(real, 1000.0) << "moment " << i << " of " << kMoments;
  }
}

}  // namespace
