// Drawing order and style of the Reeb graph overlay: halos, outlines, faded hidden nodes.
#include "render/graph_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/draw_shapes.hpp"

namespace arg {

namespace {

const Rgb kInk{30, 30, 34};
const Rgb kHalo{250, 250, 250};
constexpr double kHiddenAlpha = 0.45;

}  // namespace

double node_radius(double area, int size) {
  return std::max(3.0, size * (0.008 + 0.045 * std::sqrt(std::max(area, 0.0))));
}

std::vector<DrawnNode> draw_graph_overlay(Image& image, const ViewCamera& camera,
                                          const std::vector<OverlayNode>& nodes,
                                          const std::vector<std::pair<int, int>>& edges) {
  const int size = std::min(image.width, image.height);
  std::vector<DrawnNode> drawn(nodes.size());
  std::vector<double> z(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Eigen::Vector3d p = project(camera, nodes[i].position);
    DrawnNode& d = drawn[i];
    d.x = p.x(), d.y = p.y(), z[i] = p.z();
    d.radius = node_radius(nodes[i].area, size);
  }
  const double line = std::max(1.5, size / 256.0);
  for (int pass = 0; pass < 2; ++pass)
    for (auto [a, b] : edges) {
      const DrawnNode &p = drawn[std::size_t(a)], &q = drawn[std::size_t(b)];
      const double alpha =
          nodes[std::size_t(a)].hidden || nodes[std::size_t(b)].hidden ? kHiddenAlpha : 1.0;
      if (pass == 0) draw_line(image, p.x, p.y, q.x, q.y, line + 2, kHalo, 0.8 * alpha);
      if (pass == 1) draw_line(image, p.x, p.y, q.x, q.y, line, kInk, alpha);
    }
  std::vector<std::size_t> order(nodes.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return nodes[i].hidden != nodes[j].hidden ? nodes[i].hidden : z[i] < z[j];
  });
  for (std::size_t i : order) {
    const DrawnNode& d = drawn[i];
    const double alpha = nodes[i].hidden ? kHiddenAlpha : 1.0;
    draw_disc(image, d.x, d.y, d.radius + line, kHalo, 0.9 * alpha);
    draw_disc(image, d.x, d.y, d.radius, nodes[i].fill, alpha);
    draw_ring(image, d.x, d.y, d.radius, line, kInk, alpha);
  }
  return drawn;
}

}  // namespace arg
