// Google Benchmark of comparing two ARGs (10k-triangle models) of the same and other classes.
#include <benchmark/benchmark.h>

#include "bench_models.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"

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

}  // namespace

BENCHMARK(BM_SimSameClass)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_SimOtherClass)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_SimSameClassMrg)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_SimOctopus)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
