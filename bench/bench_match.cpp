// Google Benchmark of comparing two ARGs (10k-triangle models) of the same and other classes,
// with and without the per-graph preparation, of reading a stored value as a ranking does, of
// a ranking's row, and of what an arg_ivf index does per entry and per filed row.
#include <benchmark/benchmark.h>

#include "bench_models.hpp"
#include "graph/serialize.hpp"
#include "match/match_prep.hpp"
#include "match/packed_graph.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"
#include "search/sketch_cells.hpp"

using namespace arg;

namespace {

const ArgGraph& graph(const std::string& label, int variant) {
  static std::map<std::string, ArgGraph> cache;
  const std::string key = label + std::to_string(variant);
  auto it = cache.find(key);
  if (it == cache.end())
    it = cache.emplace(key, build_arg(bench::model_of_size(label, variant, 10000))).first;
  return it->second;
}

void compare(benchmark::State& state, const ArgGraph& a, const ArgGraph& b, const Weights& w) {
  for (auto _ : state) benchmark::DoNotOptimize(arg_similarity(a, b, w));
  state.counters["nodes"] = double(a.nodes.size() + b.nodes.size()) / 2;
}

void BM_SimSameClass(benchmark::State& state) {
  compare(state, graph("human", 0), graph("human", 2), Weights{});
}
void BM_SimOtherClass(benchmark::State& state) {
  compare(state, graph("human", 0), graph("cup", 1), Weights{});
}
void BM_SimSameClassMrg(benchmark::State& state) {
  compare(state, graph("human", 0), graph("human", 2), weights_preset("mrg"));
}
void BM_SimOctopus(benchmark::State& state) {
  compare(state, graph("octopus", 0), graph("octopus", 3), Weights{});
}

// A ranking's comparison: the query prepared once, the row not (argtool eval prepares both).
void BM_SimQueryPrepared(benchmark::State& state) {
  const ArgGraph &query = graph("human", 0), &row = graph("human", 2);
  MatchPrep prep;
  prepare_match(query, Weights{}, prep);
  for (auto _ : state)
    benchmark::DoNotOptimize(arg_similarity(row, query, Weights{}, nullptr, nullptr, &prep));
}
void BM_SimBothPrepared(benchmark::State& state) {
  const ArgGraph &a = graph("human", 0), &b = graph("human", 2);
  MatchPrep pa, pb;
  prepare_match(a, Weights{}, pa);
  prepare_match(b, Weights{}, pb);
  for (auto _ : state) benchmark::DoNotOptimize(arg_similarity(a, b, Weights{}, nullptr, &pa, &pb));
}
void BM_PrepareMatch(benchmark::State& state) {
  MatchPrep prep;
  for (auto _ : state) prepare_match(graph("human", 2), Weights{}, prep);
}

// A graph's stored bytes with its colour left out, as for most scans and every benchmark set
// (a ranking's row is read straight into the matcher's keys only without colour).
std::string stored_without_colour(ArgGraph g) {
  g.summary.has_colour = 0;
  for (ArgNode& n : g.nodes) n.colour.fill(0.0f);
  return serialize_arg(g);
}

// Reading a row's stored bytes into a graph that held another value, as the ranking's cache
// slot does (stored values were checked on input: no digest pass). Argument 1: the models'
// colour kept; 0: left out, as for most scans and every benchmark set.
void BM_ReadStoredValue(benchmark::State& state) {
  auto stored = [&](const ArgGraph& g) {
    return state.range(0) == 0 ? stored_without_colour(g) : serialize_arg(g);
  };
  const std::string a = stored(graph("human", 0)), b = stored(graph("cup", 1));
  ArgGraph slot;
  bool flip = false;
  for (auto _ : state) {
    deserialize_arg_into((flip = !flip) ? a : b, slot, /*check_digest=*/false);
    benchmark::DoNotOptimize(slot.nodes.data());
  }
  state.counters["bytes"] = double(a.size() + b.size()) / 2;
}

// A brute-force ranking's work per row in SQL, past detoasting: the row's stored bytes read
// straight into the matcher's keys, then SIM against the prepared query, alternating a row of
// the query's class and one of another (what arg_sim does on every row of ORDER BY <~>).
void BM_RankRow(benchmark::State& state) {
  const ArgGraph query = deserialize_arg(stored_without_colour(graph("human", 0)));
  MatchPrep prep;
  prepare_match(query, Weights{}, prep);
  const std::string a = stored_without_colour(graph("human", 2)),
                    b = stored_without_colour(graph("cup", 1));
  PackedGraph row;
  bool flip = false;
  for (auto _ : state) {
    double sim = 0;
    if (!read_packed_graph((flip = !flip) ? a : b, Weights{}, row) ||
        !packed_similarity(query, &prep, row, Weights{}, sim))
      state.SkipWithError("the rows did not take the packed path");
    benchmark::DoNotOptimize(sim);
  }
}

// An arg_ivf search's work per entry: the entry's sketch bytes read strictly, then its
// distance to the query's sketch.
void BM_SketchEntry(benchmark::State& state) {
  const ShapeSketch query = shape_sketch(graph("human", 0));
  const std::string a = write_shape_sketch(shape_sketch(graph("human", 2))),
                    b = write_shape_sketch(shape_sketch(graph("cup", 1)));
  ShapeSketch row;
  bool flip = false;
  for (auto _ : state) {
    read_shape_sketch((flip = !flip) ? a : b, row);
    benchmark::DoNotOptimize(sketch_distance(query, row));
  }
}

// Filing a row among 317 centres (the default cells of 100,000 rows), as the build and an
// insert do.
void BM_NearestCell(benchmark::State& state) {
  std::vector<ShapeSketch> centres;
  for (int k = 0; k < 317; ++k)
    centres.push_back(shape_sketch(graph(k % 2 ? "cup" : "human", k % 4)));
  const ShapeSketch row = shape_sketch(graph("octopus", 0));
  for (auto _ : state) benchmark::DoNotOptimize(nearest_cell(row, centres.data(), centres.size()));
}

// Every benchmark: microseconds, the median of five repetitions.
void five_repetitions(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
}

}  // namespace

BENCHMARK(BM_SketchEntry)->Apply(five_repetitions);
BENCHMARK(BM_NearestCell)->Apply(five_repetitions);
BENCHMARK(BM_RankRow)->Apply(five_repetitions);
BENCHMARK(BM_SimSameClass)->Apply(five_repetitions);
BENCHMARK(BM_SimOtherClass)->Apply(five_repetitions);
BENCHMARK(BM_SimSameClassMrg)->Apply(five_repetitions);
BENCHMARK(BM_SimOctopus)->Apply(five_repetitions);
BENCHMARK(BM_SimQueryPrepared)->Apply(five_repetitions);
BENCHMARK(BM_SimBothPrepared)->Apply(five_repetitions);
BENCHMARK(BM_PrepareMatch)->Apply(five_repetitions);
BENCHMARK(BM_ReadStoredValue)->Arg(0)->Arg(1)->Apply(five_repetitions);
