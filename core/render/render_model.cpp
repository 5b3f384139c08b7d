// Composition of a model picture: layout, supersampled surface, overlay, legend and title.
#include "render/render_model.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"
#include "render/bitmap_font.hpp"
#include "render/colour_legend.hpp"
#include "render/colour_map.hpp"

namespace arg {

int text_scale_for(int width, int height) {
  return std::min(width, height) >= 384 ? 2 : 1;
}

RenderedModel render_model(const NodePositions& model, const RenderOptions& options,
                           const std::vector<Rgb>& node_fill) {
  if (options.level < 0 || options.level >= int(model.levels.size()))
    throw InputError("render: level " + std::to_string(options.level) + " is not in 0.." +
                     std::to_string(int(model.levels.size()) - 1));
  const int ss = std::clamp(options.supersample, 1, 4);
  const int ts = text_scale_for(options.width, options.height);
  const int line = kGlyphHeight * ts;
  const int title_h = options.title.empty() ? 0 : line + 8 * ts;
  const int legend_w = options.legend ? 36 * ts : 0;
  const int margin = std::max(6, std::min(options.width, options.height) / 32);

  RenderedModel out;
  out.camera = fit_camera(model.mesh.V, options.view, 0, title_h, options.width - legend_w,
                          options.height - title_h, margin);
  ViewCamera fine = out.camera;
  fine.scale *= ss, fine.origin_x *= ss, fine.origin_y *= ss;

  SurfacePaint paint;
  paint.ramp = options.clay || options.own_colours ? std::vector<Rgb>{{214, 212, 206}}
                                                   : sample_ramp(mu_colour);
  paint.bands = options.own_colours ? 0 : 1 << options.level;
  paint.own_colours = options.own_colours;
  Image big = make_canvas(options.width * ss, options.height * ss, kRenderBackground);
  const SurfaceBuffer seen =
      rasterise_mesh(big, model.mesh, model.mu, fine, options.shading, paint);
  out.image = downsample(big, ss);

  if (options.graph) {
    const NodePlacementLevel& level = model.levels[std::size_t(options.level)];
    std::vector<OverlayNode> nodes(level.centre.size());
    // A node is hidden when no pixel shows its own surface.
    std::vector<std::size_t> shown(nodes.size(), 0);
    for (std::size_t k = 0; k < seen.face.size(); ++k) {
      if (seen.face[k] < 0) continue;
      const int n = node_at(model, options.level, seen.face[k], seen.value[k]);
      if (n >= 0 && std::size_t(n) < shown.size()) ++shown[std::size_t(n)];
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      nodes[i].hidden = shown[i] == 0;
      nodes[i].position = level.centre[i];
      nodes[i].area = level.area[i];
      if (node_fill.size() == nodes.size()) nodes[i].fill = node_fill[i];
    }
    out.nodes = draw_graph_overlay(out.image, out.camera, nodes, level.edges);
  }
  if (options.legend) {
    const int top = title_h + margin;
    draw_colour_legend(out.image, options.width - legend_w + 2 * ts, top, legend_w - 4 * ts,
                       std::min(options.height - top - margin, 220 * ts), paint, "mu", kRenderInk,
                       ts);
  }
  if (!options.title.empty()) draw_text(out.image, 4 * ts, 4 * ts, options.title, kRenderInk, ts);
  return out;
}

}  // namespace arg
