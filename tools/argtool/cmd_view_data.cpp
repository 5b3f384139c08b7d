// argtool view-data: a mesh as the browser's 3D view draws it (surface, colours, mu, nodes), JSON.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "command_registry.hpp"
#include "load_arg.hpp"
#include "pipeline/node_positions.hpp"
#include "pipeline/node_region.hpp"
#include "render/upright_frame.hpp"
#include "render_input.hpp"

namespace {

struct ViewDataArgs {
  std::string mesh, output;
  long max_triangles = 500000;
  arg::BuildOptions options;
};

// Numbers as JSON text: 6 significant digits are below a pixel on any screen; NaN cannot occur
// (the pipeline refuses non-finite input) but would be written as 0 to keep the JSON valid.
void put_number(std::string& out, double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", std::isfinite(x) ? x : 0.0);
  out += buf;
}

template <class Each>
void put_array(std::string& out, const char* key, std::size_t n, Each each) {
  out += '"';
  out += key;
  out += "\":[";
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ',';
    each(i);
  }
  out += ']';
}

int run_view_data(const ViewDataArgs& a) {
  const arg::Mesh input = argtool::read_mesh_file(a.mesh);
  if (input.F.rows() > a.max_triangles)
    throw std::runtime_error("too large to display: " + std::to_string(input.F.rows()) +
                             " triangles, more than the limit of " +
                             std::to_string(a.max_triangles));
  // The surface the graph was built on, in the ARG's frame (principal axes on x, y, z), so
  // that the nodes sit where the ARG measured them.
  const arg::NodePositions p = arg::node_positions(input, a.options);
  const arg::Mesh& m = p.mesh;
  const auto nv = std::size_t(m.V.rows()), nf = std::size_t(m.F.rows());
  std::string out = "{\"format\":1,";
  // The canonical view (argtool upright) in the same frame: the 3D view starts from it.
  const arg::UprightFrame frame = arg::upright_frame(m);
  put_array(out, "up", 3, [&](std::size_t i) { put_number(out, frame.up[long(i)]); });
  out += ',';
  put_array(out, "front", 3, [&](std::size_t i) { put_number(out, frame.front[long(i)]); });
  out += ',';
  put_array(out, "positions", 3 * nv,
            [&](std::size_t i) { put_number(out, m.V(long(i / 3), long(i % 3))); });
  out += ',';
  put_array(out, "faces", 3 * nf,
            [&](std::size_t i) { out += std::to_string(m.F(long(i / 3), long(i % 3))); });
  out += ',';
  // Per face 0..255 RGB, or none: the 3D view then shades a neutral clay.
  if (m.has_colour()) {
    put_array(out, "face_colours", 3 * nf, [&](std::size_t i) {
      out += std::to_string(
          int(std::lround(std::clamp(m.C(long(i / 3), long(i % 3)), 0.0f, 1.0f) * 255)));
    });
  } else {
    out += "\"face_colours\":null";
  }
  out += ',';
  put_array(out, "mu", nv, [&](std::size_t i) { put_number(out, p.mu[i]); });
  out += ",\"levels\":[";
  for (std::size_t r = 0; r < p.levels.size(); ++r) {
    const arg::NodePlacementLevel& level = p.levels[r];
    out += r ? ",{" : "{";
    put_array(out, "centres", 3 * level.centre.size(),
              [&](std::size_t i) { put_number(out, level.centre[i / 3][long(i % 3)]); });
    out += ',';
    put_array(out, "areas", level.area.size(),
              [&](std::size_t i) { put_number(out, level.area[i]); });
    out += ',';
    put_array(out, "edges", 2 * level.edges.size(), [&](std::size_t i) {
      out += std::to_string(i % 2 ? level.edges[i / 2].second : level.edges[i / 2].first);
    });
    out += ',';
    // The node owning each face's middle, for colouring a node's surface and for telling
    // which node a click hit.
    put_array(out, "face_nodes", nf,
              [&](std::size_t f) { out += std::to_string(arg::face_node(p, int(r), int(f))); });
    out += '}';
  }
  out += "]}\n";
  argtool::write_file_bytes(a.output, out);
  std::printf("wrote %s (%zu vertices, %zu triangles, %zu levels)\n", a.output.c_str(), nv, nf,
              p.levels.size());
  return 0;
}

const bool registered = argtool::register_command(
    "view-data",
    "a mesh as a 3D view draws it: aligned surface, colours, mu and each level's nodes, as JSON",
    [](CLI::App& app) {
      auto a = std::make_shared<ViewDataArgs>();
      app.add_option("mesh", a->mesh, "mesh file")->required()->check(CLI::ExistingFile);
      app.add_option("-o,--output", a->output, "JSON to write")->required();
      app.add_option("--max-triangles", a->max_triangles,
                     "refuse a mesh with more triangles than this (too large to display)")
          ->check(CLI::Range(1L, 100000000L))
          ->capture_default_str();
      argtool::add_build_flags(app, a->options);
      return [a] { return run_view_data(*a); };
    });

}  // namespace
