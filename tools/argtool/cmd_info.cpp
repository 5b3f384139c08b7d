// argtool info: what an ARG (or the ARG of a mesh) holds, as text or JSON.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "command_registry.hpp"
#include "load_arg.hpp"

namespace {

struct InfoArgs {
  std::string path, texture;
  bool json = false;
  arg::BuildOptions options;
};

nlohmann::json describe(const argtool::LoadedArg& loaded) {
  const arg::ArgGraph& g = loaded.graph;
  nlohmann::json j;
  j["levels"] = g.levels();
  std::vector<int> per_level;
  std::size_t edges = 0;
  for (int r = 0; r <= g.levels(); ++r)
    per_level.push_back(int(g.level_begin[std::size_t(r) + 1] - g.level_begin[std::size_t(r)]));
  edges = g.adjacency.size() / 2;
  j["nodes_per_level"] = per_level;
  j["nodes"] = g.nodes.size();
  j["edges"] = edges;
  j["triangles"] = g.summary.triangles;
  j["vertices"] = g.summary.vertices;
  j["area"] = g.summary.area;
  j["volume"] = g.summary.volume;
  j["genus_estimate"] = g.summary.genus;
  j["components"] = g.summary.components;
  j["has_colour"] = bool(g.summary.has_colour);
  j["open"] = bool(g.summary.flags & arg::kFlagOpen);
  j["proxy"] = bool(g.summary.flags & arg::kFlagProxy);
  j["wide_open"] = bool(g.summary.flags & arg::kFlagWideOpen);
  j["pooled_components"] = g.summary.pooled;
  j["format_version"] = g.format;
  j["options"] = arg::format_build_options(g.options);
  j["builder_version"] = g.builder_version;
  j["bytes"] = loaded.bytes.size();
  if (loaded.built) {
    const arg::BuildReport& r = loaded.report;
    j["input"] = {
        {"format", arg::format_name(r.read.format)}, {"vertices_read", r.read.vertices_read},
        {"faces_read", r.read.faces_read},           {"colour", r.read.colour_source},
        {"welded_vertices", r.welded_vertices},      {"dropped_degenerate", r.dropped_degenerate},
        {"dropped_duplicate", r.dropped_duplicate},  {"flipped_faces", r.flipped_faces},
        {"boundary_edges", r.boundary_edges},        {"nonmanifold_edges", r.nonmanifold_edges},
        {"stitched_pairs", r.stitched_pairs},        {"bridged_pieces", r.bridged_pieces},
        {"set_aside_pieces", r.set_aside_pieces},    {"filled_holes", r.filled_loops},
        {"smoothing_steps", r.smoothing_steps}};
    j["timings_ms"] = {{"read", r.ms.read},           {"clean", r.ms.clean},
                       {"normalise", r.ms.normalise}, {"mu", r.ms.mu},
                       {"reeb", r.ms.reeb},           {"features", r.ms.features},
                       {"serialise", r.ms.serialise}};
    j["features_ms"] = {{"smoothing", r.ms.smoothing}, {"curvature", r.ms.curvature},
                        {"nodes", r.ms.nodes},         {"global", r.ms.global},
                        {"spectrum", r.ms.spectrum},   {"views", r.ms.views}};
  }
  return j;
}

const bool registered = argtool::register_command(
    "info", "describe an ARG file, or the ARG of a mesh file", [](CLI::App& app) {
      auto a = std::make_shared<InfoArgs>();
      app.add_option("file", a->path, "ARG or mesh file")->required()->check(CLI::ExistingFile);
      app.add_option("--texture", a->texture, "texture image for OBJ")->check(CLI::ExistingFile);
      app.add_flag("--json", a->json, "print JSON");
      argtool::add_build_flags(app, a->options);
      return [a] {
        nlohmann::json j = describe(argtool::load_arg(a->path, a->options, a->texture));
        if (a->json) {
          std::cout << j.dump(2) << "\n";
        } else {
          for (auto& [key, value] : j.items()) std::cout << key << ": " << value.dump() << "\n";
        }
        return 0;
      };
    });

}  // namespace
