// Loading the models of a labelled set for eval and tune: ARGs (cached) and baseline histograms.
#pragma once

#include <string>
#include <vector>

#include "build/build_options.hpp"
#include "graph/arg_graph.hpp"

namespace argtool {

// Per-model inputs shared by all methods of one run.
struct Model {
  std::string error;  // why the model could not be used (it then counts as a miss)
  arg::ArgGraph graph;
  std::vector<float> d2, cords;
  double build_ms = 0, d2_ms = 0, cords_ms = 0;  // 0 when the ARG came from the cache
};

// Reads the mesh at `path` and fills what the methods need. Built ARGs are cached in
// `cache_dir` (when not empty) under a key of the mesh bytes, options and builder version.
// Never throws: failures land in Model::error.
void prepare_model(Model& model, const std::string& path, const arg::BuildOptions& options,
                   const std::string& cache_dir, bool need_arg, bool need_d2, bool need_cords);

}  // namespace argtool
