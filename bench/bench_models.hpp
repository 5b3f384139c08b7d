// Generated meshes of about a given size for the benchmarks (built once per process).
#pragma once

#include <map>
#include <string>

#include "gen/generate_models.hpp"

namespace arg::bench {

// A model of class `label` (variant `variant`) refined until it has at least `triangles`.
inline const Mesh& model_of_size(const std::string& label, int variant, int triangles) {
  static std::map<std::string, Mesh> cache;
  const std::string key = label + "/" + std::to_string(variant) + "/" + std::to_string(triangles);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  int resolution = 32;
  Mesh mesh = generate_model(label, variant, resolution).mesh;
  while (mesh.F.rows() < triangles && resolution < 1024) {
    resolution = int(resolution * 1.25);
    mesh = generate_model(label, variant, resolution).mesh;
  }
  return cache.emplace(key, std::move(mesh)).first->second;
}

}  // namespace arg::bench
