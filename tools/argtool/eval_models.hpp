// Loading the models of a labelled set for eval and tune: ARGs (cached) and descriptor vectors.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "common/build_options.hpp"
#include "graph/arg_graph.hpp"

namespace argtool {

// Per-model inputs shared by all methods of one run.
struct Model {
  std::string error;  // why the model could not be used (it then counts as a miss)
  arg::ArgGraph graph;
  double build_ms = 0;                                   // 0 when the ARG came from the cache
  std::map<std::string, std::vector<float>> descriptor;  // by descriptor method name
  std::map<std::string, double> descriptor_ms;
};

// Reads the mesh at `path` and fills what the methods need: the ARG when `need_arg`, and
// each descriptor method named in `descriptors`. Built ARGs are cached in `cache_dir` (when
// not empty) under a key of the mesh bytes, options and builder version. Never throws:
// failures land in Model::error.
void prepare_model(Model& model, const std::string& path, const arg::BuildOptions& options,
                   const std::string& cache_dir, bool need_arg,
                   const std::vector<std::string>& descriptors = {});

// A labelled set's name for tables: "shrec07" for ../shared/data/shrec07/labels.csv (the
// folder of a labels.csv), the file's stem for any other name.
std::string set_name(const std::string& labels_path);

}  // namespace argtool
