// Google Benchmark of cancelling a build of a 2-million-triangle mesh: poll gaps and latencies.
#include <benchmark/benchmark.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <random>

#include "common/errors.hpp"
#include "io/write_mesh.hpp"
#include "pipeline/build_arg.hpp"

using namespace arg;

namespace {

using Clock = std::chrono::steady_clock;

double since_ms(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of the calling thread (the whole build with threads=1): the gaps between polls
// without the time other processes of a busy machine take the core.
double thread_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// A torus of rows x cols x 2 triangles as binary PLY, vertices and faces shuffled as in a scan.
std::string torus_ply(int rows, int cols) {
  const int nv = rows * cols;
  std::vector<int> vertex(static_cast<std::size_t>(nv)), face(static_cast<std::size_t>(2 * nv));
  std::iota(vertex.begin(), vertex.end(), 0);
  std::iota(face.begin(), face.end(), 0);
  std::mt19937 rng(7);
  std::shuffle(vertex.begin(), vertex.end(), rng);
  std::shuffle(face.begin(), face.end(), rng);
  Mesh m;
  m.V.resize(nv, 3);
  m.F.resize(2 * nv, 3);
  auto id = [&](int i, int j) { return vertex[std::size_t((i % rows) * cols + j % cols)]; };
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double u = 2 * M_PI * i / rows, v = 2 * M_PI * j / cols;
      m.V.row(id(i, j)) << (2 + 0.6 * std::cos(v)) * std::cos(u),
          (2 + 0.6 * std::cos(v)) * std::sin(u), 0.6 * std::sin(v);
      const int f = 2 * (i * cols + j);
      m.F.row(face[std::size_t(f)]) << id(i, j), id(i, j + 1), id(i + 1, j + 1);
      m.F.row(face[std::size_t(f) + 1]) << id(i, j), id(i + 1, j + 1), id(i + 1, j);
    }
  return write_ply_binary(m);
}

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  if (x.empty()) return 0;
  const std::size_t half = x.size() / 2;
  return x.size() % 2 ? x[half] : (x[half - 1] + x[half]) / 2;
}

// Arguments: triangles / 2 as rows x 1000 columns, and the number of moments to cancel at.
// One build records every poll (largest gap, and the wait from each of the moments spread evenly
// over it to the next poll, in CPU ms), then one build per moment, spread evenly over the
// build's wall time, has its stop say yes from that moment on; the latency is the wall time from
// the moment to Interrupted reaching the caller.
void BM_BuildCancel(benchmark::State& state) {
  const std::string ply = torus_ply(int(state.range(0)), 1000);
  const int moments = int(state.range(1));
  // 2 million triangles are estimated over the default memory cap of 1 GB (and take 0.84 GB):
  // this measures the polls, so the cap is lifted.
  Limits limits;
  limits.max_build_bytes = 0;
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    const double cpu_start = thread_ms();
    double last = cpu_start, gap = 0, gap_at = 0;
    std::vector<double> polls;
    auto note = [&](double now) {
      if (now - last > gap) gap = now - last, gap_at = last - cpu_start;
      last = now;
      polls.push_back(now);
    };
    const StopRequested record = [&] {
      note(thread_ms());
      return false;
    };
    build_arg_bytes(ply, {}, BuildOptions{}, limits, record);
    note(thread_ms());
    const double total = since_ms(start);
    // The wait a cancel at each moment would see: from the moment to the next poll (CPU time).
    std::vector<double> wait;
    for (int k = 1; k <= moments; ++k) {
      const double moment = cpu_start + (last - cpu_start) * k / (moments + 1);
      wait.push_back(*std::lower_bound(polls.begin(), polls.end(), moment) - moment);
    }
    std::vector<double> latency;
    for (int k = 1; k <= moments; ++k) {
      const double moment = total * k / (moments + 1);
      const Clock::time_point begin = Clock::now();
      const StopRequested stop = [&] { return since_ms(begin) >= moment; };
      try {
        build_arg_bytes(ply, {}, BuildOptions{}, limits, stop);
        state.SkipWithError("a build ran to its end past its stop");
      } catch (const Interrupted&) {
        latency.push_back(since_ms(begin) - moment);
      }
    }
    state.counters["build_ms"] = total;
    state.counters["cpu_ms"] = last - cpu_start;
    state.counters["polls"] = double(polls.size());
    state.counters["largest_gap_cpu_ms"] = gap;
    state.counters["gap_at_cpu_ms"] = gap_at;
    state.counters["wait_median_cpu_ms"] = median(wait);
    state.counters["wait_max_cpu_ms"] = *std::max_element(wait.begin(), wait.end());
    state.counters["latency_median_ms"] = median(latency);
    state.counters["latency_max_ms"] =
        latency.empty() ? 0 : *std::max_element(latency.begin(), latency.end());
  }
  state.counters["triangles"] = double(state.range(0)) * 2000;
}

// 200,000 triangles and 5 moments for a quick look; 2,000,000 and 20 for docs/BENCHMARKS.md.
BENCHMARK(BM_BuildCancel)
    ->Args({100, 5})
    ->Args({1000, 20})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
