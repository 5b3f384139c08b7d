// One picture of a model: its lit surface coloured by mu, its Reeb graph on top, a legend.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "pipeline/node_positions.hpp"
#include "render/canvas.hpp"
#include "render/graph_overlay.hpp"
#include "render/rasterise_mesh.hpp"
#include "render/view_camera.hpp"

namespace arg {

struct RenderOptions {
  int width = 512, height = 512;
  int level = 2;  // the Reeb graph level drawn, and the stripes of mu on the surface
  Eigen::Matrix3d view = view_rotation(0, 0);
  Shading shading = Shading::Smooth;
  // A neutral grey surface instead of mu colours, for pictures whose node colours carry the
  // meaning (matched pairs); the mu intervals still show as stripes.
  bool clay = false;
  // The surface in its own colours (per face, where the mesh has them; clay otherwise), without
  // the mu stripes: the object as it looks.
  bool own_colours = false;
  bool legend = true;
  bool graph = true;
  std::string title;    // drawn at the top left when not empty
  int supersample = 2;  // the surface is drawn this many times larger, then averaged down
};

struct RenderedModel {
  Image image;
  ViewCamera camera;             // maps model coordinates to pixels of `image`
  std::vector<DrawnNode> nodes;  // node k of the level, as drawn (empty without the graph)
};

inline const Rgb kRenderBackground{255, 255, 255};
inline const Rgb kRenderInk{34, 34, 40};

// Text scale that keeps the 5x7 font readable at the picture's size.
int text_scale_for(int width, int height);

// Renders `model` (from node_positions) as described by `options`; `node_fill`, when it has
// one colour per node of the level, paints the discs (white otherwise). Deterministic: the same
// input gives the same pixels. Throws InputError for a level the model does not have.
RenderedModel render_model(const NodePositions& model, const RenderOptions& options,
                           const std::vector<Rgb>& node_fill = {});

}  // namespace arg
