// argtool render: a lit picture of a mesh coloured by mu with its Reeb graph drawn on top.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "command_registry.hpp"
#include "load_arg.hpp"
#include "pipeline/node_positions.hpp"
#include "plugin_libraries.hpp"
#include "render/graph_svg.hpp"
#include "render/render_model.hpp"
#include "render/upright_frame.hpp"
#include "render_input.hpp"
#include "up_option.hpp"

namespace {

struct RenderArgs {
  std::string mesh, output, view = "front", shading = "smooth", title, surface = "mu";
  std::string colours_output;  // also the surface in its own colours, without the graph
  std::string up;              // the file axis that points up, for --view upright
  std::string texture;         // an OBJ's texture image, for its own colours
  int level = 2, size = 512;
  bool no_legend = false, no_graph = false;
  arg::BuildOptions options;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

int run_render(const RenderArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  if (ends_with(a.output, ".svg") || ends_with(a.output, ".SVG")) {
    // The graph alone needs no surface, so an ARG file will do as well as a mesh.
    const argtool::LoadedArg loaded = argtool::load_arg(a.mesh, a.options);
    argtool::write_file_bytes(a.output, arg::arg_graph_svg(loaded.graph, a.level));
    std::printf("wrote %s (graph at level %d)\n", a.output.c_str(), a.level);
    return 0;
  }
  arg::RenderOptions ro;
  ro.width = ro.height = a.size;
  ro.level = a.level;
  // "upright" depends on the surface, so it is made once the surface is there.
  if (a.view != "upright") ro.view = arg::parse_view(a.view);
  ro.shading = arg::parse_shading(a.shading);
  ro.own_colours = a.surface == "colours";
  ro.legend = !a.no_legend && !ro.own_colours;  // a legend of mu explains mu colours only
  ro.graph = !a.no_graph;
  if (a.level > a.options.levels)
    throw std::runtime_error("--level " + std::to_string(a.level) + " is finer than --levels " +
                             std::to_string(a.options.levels));
  // A model built on its proxy is drawn as itself, mu and the nodes carried over from the proxy.
  const arg::NodePositions model = arg::node_positions(argtool::read_mesh_file(a.mesh, a.texture),
                                                       a.options, {}, arg::ShownSurface::Own);
  if (a.view == "upright") {
    // The surface is posed: the file's axes are the pose's columns.
    ro.view = arg::upright_view(
        arg::upright_frame(model.mesh, argtool::upright_hint(a.mesh, a.up, model.pose.rotation)));
  }
  const std::size_t nodes = model.levels[std::size_t(a.level)].centre.size();
  ro.title = a.title.empty() ? std::filesystem::path(a.mesh).filename().string() + "  level " +
                                   std::to_string(a.level) + ": " + std::to_string(nodes) +
                                   (nodes == 1 ? " node" : " nodes")
                             : a.title;
  const arg::RenderedModel picture = arg::render_model(model, ro);
  argtool::write_png(picture.image, a.output);
  if (!a.colours_output.empty()) {
    // From the same surface: mu and the graph are the costly part, computed once for both.
    arg::RenderOptions plain = ro;
    plain.own_colours = true, plain.legend = false, plain.graph = false;
    argtool::write_png(arg::render_model(model, plain).image, a.colours_output);
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s (%dx%d, level %d: %zu nodes drawn, %.0f ms)\n", a.output.c_str(),
              picture.image.width, picture.image.height, a.level, picture.nodes.size(), ms);
  return 0;
}

const bool registered = argtool::register_command(
    "render", "draw a mesh coloured by mu with its Reeb graph on top, as PNG (or the graph as SVG)",
    [](CLI::App& app) {
      auto a = std::make_shared<RenderArgs>();
      app.add_option("mesh", a->mesh, "mesh file (OFF, OBJ, PLY, STL, GLB); an ARG file for .svg")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("-o,--output", a->output,
                     "PNG to write; a name ending in .svg writes the graph alone as SVG")
          ->required();
      app.add_option("--level", a->level, "Reeb graph level to draw (0 = coarsest)")
          ->check(CLI::Range(0, arg::kMaxLevels))
          ->capture_default_str();
      app.add_option("--size", a->size, "width and height in pixels")
          ->check(CLI::Range(64, 4096))
          ->capture_default_str();
      app.add_option(
             "--view", a->view,
             "front, side, top, AZIMUTH,ELEVATION[,ROLL] in degrees (principal axes, the longest "
             "upright), or upright (resting on its broadest base, argtool upright)")
          ->capture_default_str();
      argtool::add_up_option(app, a->up);
      app.add_option("--shading", a->shading, "flat or smooth")
          ->check(CLI::IsMember({"flat", "smooth"}))
          ->capture_default_str();
      app.add_option("--title", a->title, "caption (default: file name, level, node count)");
      app.add_flag("--no-legend", a->no_legend, "leave out the colour legend");
      app.add_flag("--no-graph", a->no_graph, "draw the surface only");
      app.add_option("--surface", a->surface,
                     "mu (coloured by mu, striped by the level's intervals) or colours (the "
                     "model's own colours, clay where it has none)")
          ->check(CLI::IsMember({"mu", "colours"}))
          ->capture_default_str();
      app.add_option("--texture", a->texture,
                     "texture image for OBJ: the own colours are sampled from it, as the ARG's are")
          ->check(CLI::ExistingFile);
      app.add_option("--colours-output", a->colours_output,
                     "a second PNG from the same surface: its own colours, no graph or legend");
      argtool::add_build_flags(app, a->options);
      return [a] { return run_render(*a); };
    });

}  // namespace
