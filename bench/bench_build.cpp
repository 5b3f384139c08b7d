// Google Benchmark of each stage of an ARG build on 10k- and 100k-triangle meshes.
#include <benchmark/benchmark.h>

#include "bench_models.hpp"
#include "features/curvature.hpp"
#include "features/node_attributes.hpp"
#include "graph/serialize.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "mesh/clean_mesh.hpp"
#include "mesh/collapse_short_edges.hpp"
#include "mesh/mesh_edges.hpp"
#include "mesh/normalize_pose.hpp"
#include "mesh/surface_area.hpp"
#include "mesh/taubin_smoothing.hpp"
#include "mu/mu_function.hpp"
#include "pipeline/build_arg.hpp"
#include "reeb/reeb_levels.hpp"
#include "reeb/slice_intervals.hpp"

using namespace arg;

namespace {

const Mesh& input(const benchmark::State& state) {
  return bench::model_of_size("human", 1, int(state.range(0)));
}

// The pose-normalised, cleaned mesh and its mu, as the later stages see them.
struct Prepared {
  Mesh mesh;
  MeshEdges edges;
  std::vector<double> mu;
};
const Prepared& prepared(const benchmark::State& state) {
  static std::map<long, Prepared> cache;
  auto it = cache.find(state.range(0));
  if (it != cache.end()) return it->second;
  Prepared p;
  p.mesh = clean_mesh(input(state));
  p.mesh = apply_pose(p.mesh, surface_pose(p.mesh));
  p.edges = mesh_edges(p.mesh.F);
  p.mu = normalised_mu(p.mesh, p.edges, BuildOptions{});
  return cache.emplace(state.range(0), std::move(p)).first->second;
}

void set_counters(benchmark::State& state) {
  state.counters["triangles"] = double(input(state).F.rows());
}

void BM_ReadOff(benchmark::State& state) {
  const std::string bytes = write_off(input(state));
  for (auto _ : state) benchmark::DoNotOptimize(read_mesh(bytes));
  set_counters(state);
}

void BM_Clean(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(clean_mesh(input(state)));
  set_counters(state);
}

void BM_Pose(benchmark::State& state) {
  const Mesh& m = prepared(state).mesh;
  for (auto _ : state) benchmark::DoNotOptimize(apply_pose(m, surface_pose(m)));
  set_counters(state);
}

// The 80 pairs of Taubin steps a rough surface takes before its curvature and views.
void BM_Smoothing(benchmark::State& state) {
  const Prepared& p = prepared(state);
  for (auto _ : state) benchmark::DoNotOptimize(taubin_smoothing(p.mesh, p.edges, 80));
  set_counters(state);
}

// The collapse of the spectrum's copy: edges shorter than those of 10,000 equilateral triangles.
void BM_Collapse(benchmark::State& state) {
  const Prepared& p = prepared(state);
  CollapseOptions options;
  options.min_length = std::sqrt(4.0 * surface_area(p.mesh) / (std::sqrt(3.0) * 10000.0));
  std::vector<int> map;
  for (auto _ : state) benchmark::DoNotOptimize(collapse_short_edges(p.mesh, options, {}, &map));
  set_counters(state);
}

void BM_MuGeodesic(benchmark::State& state) {
  const Prepared& p = prepared(state);
  for (auto _ : state) benchmark::DoNotOptimize(normalised_mu(p.mesh, p.edges, BuildOptions{}));
  set_counters(state);
}

void BM_SliceAndReeb(benchmark::State& state) {
  const Prepared& p = prepared(state);
  for (auto _ : state) {
    SlicedSurface s = slice_intervals(p.mesh, p.mu, 32);
    benchmark::DoNotOptimize(reeb_levels(s, p.edges, 5));
  }
  set_counters(state);
}

void BM_Features(benchmark::State& state) {
  const Prepared& p = prepared(state);
  SlicedSurface s = slice_intervals(p.mesh, p.mu, 32);
  ReebGraph reeb = reeb_levels(s, p.edges, 5);
  for (auto _ : state) {
    TriangleCurvature c = triangle_curvature(p.mesh, p.edges);
    benchmark::DoNotOptimize(node_attributes(p.mesh, s, reeb, c));
  }
  set_counters(state);
}

void BM_Serialise(benchmark::State& state) {
  ArgGraph g = build_arg(input(state));
  for (auto _ : state) benchmark::DoNotOptimize(serialize_arg(g));
  set_counters(state);
}

void BM_Deserialise(benchmark::State& state) {
  const std::string bytes = serialize_arg(build_arg(input(state)));
  for (auto _ : state) benchmark::DoNotOptimize(deserialize_arg(bytes));
  set_counters(state);
}

void BM_WholeBuild(benchmark::State& state) {
  const std::string bytes = write_off(input(state));
  for (auto _ : state) benchmark::DoNotOptimize(build_arg_bytes(bytes, {}));
  set_counters(state);
}

}  // namespace

#define STAGE(fn) \
  BENCHMARK(fn)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->MinTime(0.5)
STAGE(BM_ReadOff);
STAGE(BM_Clean);
STAGE(BM_Pose);
STAGE(BM_Smoothing);
STAGE(BM_Collapse);
STAGE(BM_MuGeodesic);
STAGE(BM_SliceAndReeb);
STAGE(BM_Features);
STAGE(BM_Serialise);
BENCHMARK(BM_Deserialise)->Arg(10000)->Unit(benchmark::kMicrosecond);
STAGE(BM_WholeBuild);

namespace {
void BM_DeserialiseWithoutDigest(benchmark::State& state) {
  const std::string bytes = serialize_arg(build_arg(input(state)));
  for (auto _ : state) benchmark::DoNotOptimize(deserialize_arg(bytes, false));
  set_counters(state);
}
// A value's way in and out as text, as COPY takes it: arg_in checks every byte and the digest.
void BM_ValueFromText(benchmark::State& state) {
  const std::string text = arg_to_text(serialize_arg(build_arg(input(state))));
  for (auto _ : state) benchmark::DoNotOptimize(arg_from_text(text));
  set_counters(state);
}
void BM_ValueToText(benchmark::State& state) {
  const std::string bytes = serialize_arg(build_arg(input(state)));
  for (auto _ : state) benchmark::DoNotOptimize(arg_to_text(bytes));
  set_counters(state);
}
}  // namespace
BENCHMARK(BM_DeserialiseWithoutDigest)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ValueFromText)->Arg(10000)->Unit(benchmark::kMicrosecond)->Repetitions(5);
BENCHMARK(BM_ValueToText)->Arg(10000)->Unit(benchmark::kMicrosecond)->Repetitions(5);
