// Google Benchmark of whole builds on labelled models (../shared): one thread, CPU time a model.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "eval/label_file.hpp"
#include "eval/refine_faces.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "pipeline/build_arg.hpp"

using namespace arg;

namespace {

// The labelled sets, where the quality harness reads them; ARG_SHARED_DATA overrides.
std::string data_root() {
  const char* root = std::getenv("ARG_SHARED_DATA");
  return root ? root : "../shared/data";
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// Every `step`-th model of a set (label order), as its file's bytes; empty when the set is absent.
std::vector<std::string> every_nth(const std::string& set, std::size_t step) {
  const std::string dir = data_root() + "/" + set;
  std::vector<std::string> bytes;
  if (!std::ifstream(dir + "/labels.csv")) return bytes;
  const LabelSet set_labels = parse_label_csv(file_bytes(dir + "/labels.csv"));
  for (std::size_t i = 0; i < set_labels.models.size(); i += step)
    bytes.push_back(file_bytes(dir + "/" + set_labels.models[i].path));
  return bytes;
}

// A high-resolution stand-in for a scan: the model's faces cut into four (a conforming
// refinement, the shape unchanged) until it has at least `triangles`, written as PLY.
std::string refined(const std::string& bytes, Eigen::Index triangles) {
  Mesh mesh = read_mesh(bytes);
  while (mesh.F.rows() < triangles) {
    double longest = 0;
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest,
                           (mesh.V.row(mesh.F(f, k)) - mesh.V.row(mesh.F(f, (k + 1) % 3))).norm());
    const Eigen::Index before = mesh.F.rows();
    mesh = refine_faces(
        mesh, 0.5 * longest, [](auto&, auto&, auto&) { return true; }, 2 * triangles);
    if (mesh.F.rows() == before) break;
  }
  return write_ply_binary(mesh);
}

// An iteration builds one model, the next each time: with as many iterations as models, the
// time an iteration is the mean over the models, and the repetitions give its median.
void build_each(benchmark::State& state, const std::vector<std::string>& models,
                const char* absent) {
  if (models.empty() || state.max_iterations != std::int64_t(models.size())) {
    state.SkipWithError(models.empty() ? absent : "the models are not the set's expected count");
    return;
  }
  BuildOptions options;
  options.threads = 1;
  std::size_t next = 0;
  for (auto _ : state) benchmark::DoNotOptimize(build_arg_bytes(models[next++], {}, options));
}

// SHREC 2007, every tenth model: 40 closed models of the set's median size.
void BM_BuildShrec07Tenth(benchmark::State& state) {
  static const std::vector<std::string> models = every_nth("shrec07", 10);
  build_each(state, models, "skipped: ../shared/data/shrec07 is absent");
}

// SHREC 2011, every fifteenth model refined to 60,000 triangles or more (30,000-50,000
// vertices), as a high-resolution scan would come.
void BM_BuildShrec11Refined(benchmark::State& state) {
  static const std::vector<std::string> models = [] {
    std::vector<std::string> out;
    for (const std::string& bytes : every_nth("shrec11", 15)) out.push_back(refined(bytes, 60000));
    return out;
  }();
  build_each(state, models, "skipped: ../shared/data/shrec11 is absent");
}

}  // namespace

// Iterations: the models each builds (400 / 10 and 154 / 15, rounded up).
BENCHMARK(BM_BuildShrec07Tenth)->Unit(benchmark::kMillisecond)->Iterations(40)->Repetitions(5);
BENCHMARK(BM_BuildShrec11Refined)->Unit(benchmark::kMillisecond)->Iterations(11)->Repetitions(5);
