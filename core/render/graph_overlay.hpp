// The Reeb graph drawn over a rendered mesh: nodes as discs at their barycentres, edges as lines.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "render/canvas.hpp"
#include "render/view_camera.hpp"

namespace arg {

struct OverlayNode {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // model coordinates
  double area = 0;                                     // share of its level's surface
  Rgb fill{255, 255, 255};
  bool hidden = false;  // none of its surface shows in this view: drawn faded
};

// Where a node ended up in the picture.
struct DrawnNode {
  double x = 0, y = 0, radius = 0;
};

// Disc radius in pixels for a node of the given area share in a picture of `size` pixels: the
// area of the disc grows with the node's area, never below a few pixels.
double node_radius(double area, int size);

// Draws the edges, then the nodes from the farthest to the nearest, all on top of the surface
// (a barycentre usually lies inside its part), with dark outlines and a light halo so they read
// on any surface colour; hidden nodes and their edges are faded. Returns one entry per node, in
// the order of `nodes`.
std::vector<DrawnNode> draw_graph_overlay(Image& image, const ViewCamera& camera,
                                          const std::vector<OverlayNode>& nodes,
                                          const std::vector<std::pair<int, int>>& edges);

}  // namespace arg
