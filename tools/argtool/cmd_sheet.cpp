// argtool sheet: a contact sheet of a query and its best-ranked candidates, with their SIM.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "command_registry.hpp"
#include "load_arg.hpp"
#include "match/similarity.hpp"
#include "mesh_files.hpp"
#include "plugin_libraries.hpp"
#include "render/contact_sheet.hpp"
#include "render/render_model.hpp"
#include "render_input.hpp"

namespace {

namespace fs = std::filesystem;

struct SheetArgs {
  std::string query, folder, output, weights = "arg", view = "front";
  std::vector<std::string> candidates;
  int top = 8, thumb = 192, columns = 5, level = 2;
  bool no_graph = false;
  arg::BuildOptions options;
};

// The candidates named on the command line, then the mesh files of the folder sorted by name,
// without the query itself.
std::vector<std::string> candidate_paths(const SheetArgs& a) {
  std::vector<std::string> paths = a.candidates;
  if (!a.folder.empty()) {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(a.folder))
      if (entry.is_regular_file() && argtool::is_mesh_file(entry.path()))
        found.push_back(entry.path().string());
    std::sort(found.begin(), found.end());
    paths.insert(paths.end(), found.begin(), found.end());
  }
  std::error_code ec;
  paths.erase(std::remove_if(paths.begin(), paths.end(),
                             [&](const std::string& p) { return fs::equivalent(p, a.query, ec); }),
              paths.end());
  return paths;
}

std::string fixed(double x, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

int run_sheet(const SheetArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  if (a.level > a.options.levels)
    throw std::runtime_error("--level " + std::to_string(a.level) + " is finer than --levels " +
                             std::to_string(a.options.levels));
  const arg::Weights w = arg::parse_weights(a.weights);
  const std::vector<std::string> paths = candidate_paths(a);
  if (paths.empty()) throw std::runtime_error("no candidates: name mesh files or give --folder");

  const argtool::RenderInput query = argtool::load_render_input(a.query, a.options);
  struct Ranked {
    argtool::RenderInput input;
    double sim = 0;
  };
  std::vector<Ranked> ranked;
  for (const std::string& path : paths) {
    // Positions (a second mu computation) only for the few that will be drawn, below.
    try {
      Ranked r{argtool::load_render_input(path, a.options, false), 0};
      r.sim = arg::arg_similarity(query.graph, r.input.graph, w);
      ranked.push_back(std::move(r));
    } catch (const std::exception& e) {
      // One unreadable file in a folder should not cost the whole sheet.
      std::fprintf(stderr, "argtool sheet: skipping %s\n", e.what());
    }
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& x, const Ranked& y) {
    return x.sim != y.sim ? x.sim < y.sim : x.input.name < y.input.name;
  });
  if (ranked.empty()) throw std::runtime_error("no candidate could be read");
  const std::size_t shown = std::min(ranked.size(), std::size_t(a.top));

  arg::RenderOptions ro;
  ro.width = ro.height = a.thumb;
  ro.level = a.level;
  ro.legend = false;
  ro.view = arg::parse_view(a.view);
  ro.graph = !a.no_graph;
  std::vector<arg::SheetCell> cells;
  arg::SheetCell q;
  q.picture = arg::render_model(query.positions, ro).image;
  q.caption = {"query", query.name};
  q.framed = true;
  cells.push_back(std::move(q));
  for (std::size_t k = 0; k < shown; ++k) {
    arg::SheetCell c;
    const arg::NodePositions positions =
        arg::node_positions(argtool::read_mesh_file(ranked[k].input.path), a.options);
    c.picture = arg::render_model(positions, ro).image;
    c.caption = {"#" + std::to_string(k + 1) + "  SIM " + fixed(ranked[k].sim, 4),
                 ranked[k].input.name};
    cells.push_back(std::move(c));
  }
  const std::string title = "query " + query.name + ": best " + std::to_string(shown) + " of " +
                            std::to_string(ranked.size()) + " by SIM (weights " + a.weights +
                            ", level " + std::to_string(a.level) + " graph shown)";
  const arg::Image sheet = arg::contact_sheet(cells, a.columns, title, a.thumb >= 256 ? 2 : 1);
  argtool::write_png(sheet, a.output);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (std::size_t k = 0; k < shown; ++k)
    std::printf("%2zu  %.6f  %s\n", k + 1, ranked[k].sim, ranked[k].input.path.c_str());
  std::printf("wrote %s (%dx%d, %zu of %zu candidates, %.0f ms)\n", a.output.c_str(), sheet.width,
              sheet.height, shown, ranked.size(), ms);
  return 0;
}

const bool registered = argtool::register_command(
    "sheet", "draw a contact sheet of a query and its best matches by SIM, as PNG",
    [](CLI::App& app) {
      auto a = std::make_shared<SheetArgs>();
      app.add_option("query", a->query, "query mesh file")->required()->check(CLI::ExistingFile);
      app.add_option("candidates", a->candidates, "candidate mesh files")->check(CLI::ExistingFile);
      app.add_option("--folder", a->folder, "also rank every mesh file in this folder")
          ->check(CLI::ExistingDirectory);
      app.add_option("-o,--output", a->output, "PNG to write")->required();
      app.add_option("--top", a->top, "results shown")
          ->check(CLI::Range(1, 200))
          ->capture_default_str();
      app.add_option("--weights", a->weights,
                     "preset (arg, part, mrg, graph, shape, colour) or key=value text")
          ->capture_default_str();
      app.add_option("--thumb", a->thumb, "thumbnail size in pixels")
          ->check(CLI::Range(64, 1024))
          ->capture_default_str();
      app.add_option("--columns", a->columns, "thumbnails per row")
          ->check(CLI::Range(1, 50))
          ->capture_default_str();
      app.add_option("--level", a->level, "Reeb graph level drawn on the thumbnails")
          ->check(CLI::Range(0, arg::kMaxLevels))
          ->capture_default_str();
      app.add_option("--view", a->view,
                     "front, side, top or AZIMUTH,ELEVATION[,ROLL] in degrees, for every model")
          ->capture_default_str();
      app.add_flag("--no-graph", a->no_graph, "thumbnails without the graph");
      argtool::add_build_flags(app, a->options);
      return [a] { return run_sheet(*a); };
    });

}  // namespace
