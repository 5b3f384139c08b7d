// Edge-function rasterisation with a top-left fill rule and per-pixel Blinn-Phong lighting.
#include "render/rasterise_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"

namespace arg {

namespace {

constexpr float kEmpty = -std::numeric_limits<float>::infinity();

// Lights in view space (right, up, towards the viewer).
const Eigen::Vector3d kKey = Eigen::Vector3d(-0.45, 0.55, 1.0).normalized();
const Eigen::Vector3d kFill = Eigen::Vector3d(0.7, -0.25, 0.55).normalized();
const Eigen::Vector3d kHalf = (kKey + Eigen::Vector3d::UnitZ()).normalized();

Rgb lit(Rgb base, Eigen::Vector3d n) {
  if (n.z() < 0) n = -n;  // the side facing the viewer
  const double diffuse = 0.62 * std::max(n.dot(kKey), 0.0) + 0.22 * std::max(n.dot(kFill), 0.0);
  const double k = 0.32 + diffuse;
  const double spec = 0.18 * std::pow(std::max(n.dot(kHalf), 0.0), 28.0) * 255;
  auto channel = [&](std::uint8_t c) {
    return std::uint8_t(std::clamp(std::lround(c * k + spec), 0L, 255L));
  };
  return {channel(base.r), channel(base.g), channel(base.b)};
}

// True when the edge a -> b is a top or left edge of a counter-clockwise (in pixel space,
// y down: clockwise on screen) triangle; pixels exactly on such edges belong to the triangle.
bool top_left(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d e = b - a;
  return (e.y() == 0 && e.x() > 0) || e.y() < 0;
}

}  // namespace

Shading parse_shading(std::string_view text) {
  if (text == "flat") return Shading::Flat;
  if (text == "smooth") return Shading::Smooth;
  throw InputError("render: shading must be flat or smooth, not '" + std::string(text) + "'");
}

SurfaceBuffer rasterise_mesh(Image& image, const Mesh& mesh, const std::vector<double>& value,
                             const ViewCamera& camera, Shading shading, const SurfacePaint& paint) {
  if (value.size() != std::size_t(mesh.V.rows()))
    throw InputError("render: one value per vertex is needed");
  if (paint.ramp.empty()) throw InputError("render: empty colour ramp");
  SurfaceBuffer out;
  out.width = image.width, out.height = image.height;
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  out.depth.assign(pixels, kEmpty);
  out.face.assign(pixels, -1);
  out.value.assign(pixels, 0.0f);

  const auto nv = static_cast<std::size_t>(mesh.V.rows());
  const auto nf = static_cast<std::size_t>(mesh.F.rows());
  auto corner = [&](std::size_t f, int k) {
    return static_cast<std::size_t>(mesh.F(Eigen::Index(f), k));
  };
  std::vector<Eigen::Vector3d> screen(nv), normal(nv), face_normal(nf);
  for (std::size_t i = 0; i < nv; ++i)
    screen[i] = project(camera, mesh.V.row(Eigen::Index(i)).transpose());
  // Normals in view space; vertex normals sum the faces' area vectors.
  for (std::size_t f = 0; f < nf; ++f) {
    const Eigen::Vector3d a = mesh.V.row(Eigen::Index(corner(f, 0))),
                          b = mesh.V.row(Eigen::Index(corner(f, 1))),
                          c = mesh.V.row(Eigen::Index(corner(f, 2)));
    face_normal[f] = camera.rotation * (b - a).cross(c - a);
  }
  if (shading == Shading::Smooth) {
    std::fill(normal.begin(), normal.end(), Eigen::Vector3d::Zero());
    for (std::size_t f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) normal[corner(f, k)] += face_normal[f];
    for (auto& n : normal) n = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : n;
  }
  for (auto& n : face_normal) n = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : n;

  const int steps = int(paint.ramp.size());
  const bool own = paint.own_colours && mesh.has_colour();
  auto channel = [](float c) { return std::uint8_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255)); };
  for (std::size_t f = 0; f < nf; ++f) {
    std::size_t id[3] = {corner(f, 0), corner(f, 1), corner(f, 2)};
    Eigen::Vector2d p[3] = {screen[id[0]].head<2>(), screen[id[1]].head<2>(),
                            screen[id[2]].head<2>()};
    double area = (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
    if (!(std::fabs(area) > 1e-12)) continue;
    if (area < 0) std::swap(p[1], p[2]), std::swap(id[1], id[2]), area = -area;
    const int x0 = std::max(0, int(std::floor(std::min({p[0].x(), p[1].x(), p[2].x()})))),
              x1 = std::min(image.width - 1,
                            int(std::ceil(std::max({p[0].x(), p[1].x(), p[2].x()})))),
              y0 = std::max(0, int(std::floor(std::min({p[0].y(), p[1].y(), p[2].y()})))),
              y1 = std::min(image.height - 1,
                            int(std::ceil(std::max({p[0].y(), p[1].y(), p[2].y()}))));
    bool owns[3];
    for (int e = 0; e < 3; ++e) owns[e] = top_left(p[(e + 1) % 3], p[(e + 2) % 3]);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2d c(x + 0.5, y + 0.5);
        double w[3];
        bool inside = true;
        for (int e = 0; e < 3 && inside; ++e) {
          const Eigen::Vector2d& a = p[(e + 1) % 3];
          const Eigen::Vector2d& b = p[(e + 2) % 3];
          w[e] = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
          inside = w[e] > 0 || (w[e] == 0 && owns[e]);
        }
        if (!inside) continue;
        for (double& k : w) k /= area;
        const double z =
            w[0] * screen[id[0]].z() + w[1] * screen[id[1]].z() + w[2] * screen[id[2]].z();
        const std::size_t at = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
        if (!(float(z) > out.depth[at])) continue;
        out.depth[at] = float(z);
        out.face[at] = int(f);
        const double t =
            std::clamp(w[0] * value[id[0]] + w[1] * value[id[1]] + w[2] * value[id[2]], 0.0, 1.0);
        out.value[at] = float(t);
        Rgb base = paint.ramp[std::size_t(std::lround(t * (steps - 1)))];
        if (own)
          base = {channel(mesh.C(Eigen::Index(f), 0)), channel(mesh.C(Eigen::Index(f), 1)),
                  channel(mesh.C(Eigen::Index(f), 2))};
        else if (paint.bands > 0 && std::min(int(t * paint.bands), paint.bands - 1) % 2)
          base = scaled(base, 0.8);
        const Eigen::Vector3d n = shading == Shading::Smooth
                                      ? Eigen::Vector3d(w[0] * normal[id[0]] +
                                                        w[1] * normal[id[1]] + w[2] * normal[id[2]])
                                      : face_normal[f];
        const double len = n.norm();
        const Rgb shaded = lit(base, len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::UnitZ());
        std::uint8_t* px = &image.rgb[at * 3];
        px[0] = shaded.r, px[1] = shaded.g, px[2] = shaded.b;
      }
  }
  return out;
}

}  // namespace arg
