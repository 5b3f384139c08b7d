// Preparing labelled models for the quality harness, with an on-disk cache of built ARGs.
#include "eval_models.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "command_registry.hpp"
#include "common/hash.hpp"
#include "eval/baseline_descriptors.hpp"
#include "graph/serialize.hpp"
#include "io/read_mesh.hpp"
#include "pipeline/build_arg.hpp"

namespace fs = std::filesystem;

namespace argtool {

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

namespace {

std::string cache_path(const std::string& dir, const std::string& mesh,
                       const arg::BuildOptions& o) {
  std::uint64_t key = arg::fnv1a_64(
      mesh, arg::fnv1a_64(arg::format_build_options(o) +
                          " builder=" + std::to_string(arg::current_builder_version())));
  char name[40];
  std::snprintf(name, sizeof name, "%016llx.arg", static_cast<unsigned long long>(key));
  return (fs::path(dir) / name).string();
}
}  // namespace

void prepare_model(Model& m, const std::string& path, const arg::BuildOptions& options,
                   const std::string& cache_dir, bool need_arg,
                   const std::vector<std::string>& descriptors) {
  try {
    std::string bytes = argtool::read_file_bytes(path);
    if (need_arg) {
      std::string cached = cache_dir.empty() ? "" : cache_path(cache_dir, bytes, options);
      std::string arg_bytes;
      if (!cached.empty() && fs::exists(cached)) {
        arg_bytes = argtool::read_file_bytes(cached);
      } else {
        auto t0 = std::chrono::steady_clock::now();
        arg_bytes = arg::build_arg_bytes(bytes, {}, options);
        m.build_ms = ms_since(t0);
        if (!cached.empty()) argtool::write_file_bytes(cached, arg_bytes);
      }
      m.graph = arg::deserialize_arg(arg_bytes);
    }
    if (!descriptors.empty()) {
      const arg::Mesh posed = arg::posed_for_descriptors(arg::read_mesh(bytes));
      for (const std::string& name : descriptors) {
        const arg::DescriptorMethod* method = arg::find_descriptor_method(name);
        if (!method) throw std::runtime_error("no descriptor method " + name);
        auto t0 = std::chrono::steady_clock::now();
        m.descriptor[name] = method->compute(posed);
        m.descriptor_ms[name] = ms_since(t0);
      }
    }
  } catch (const std::exception& e) {
    m.error = e.what();
  }
}

std::string set_name(const std::string& labels) {
  const fs::path p(labels);
  if (p.filename() == "labels.csv" && p.has_parent_path() && !p.parent_path().filename().empty())
    return p.parent_path().filename().string();
  return p.stem().string();
}

}  // namespace argtool
