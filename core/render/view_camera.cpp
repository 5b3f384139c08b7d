// View rotations from azimuth and elevation, view names, and fitting a projection to a frame.
#include "render/view_camera.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/errors.hpp"

namespace arg {

Eigen::Matrix3d view_rotation(double azimuth_degrees, double elevation_degrees,
                              double roll_degrees) {
  const double az = azimuth_degrees * M_PI / 180, el = elevation_degrees * M_PI / 180;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d around =
      std::cos(az) * Eigen::Vector3d::UnitZ() + std::sin(az) * Eigen::Vector3d::UnitY();
  const Eigen::Vector3d toward = std::cos(el) * around + std::sin(el) * x;
  const Eigen::Vector3d up = -std::sin(el) * around + std::cos(el) * x;
  const Eigen::Vector3d right = up.cross(toward);
  const double roll = roll_degrees * M_PI / 180;
  Eigen::Matrix3d r;
  r.row(0) = std::cos(roll) * right - std::sin(roll) * up;
  r.row(1) = std::sin(roll) * right + std::cos(roll) * up;
  r.row(2) = toward;
  return r;
}

Eigen::Matrix3d parse_view(std::string_view view) {
  if (view == "front") return view_rotation(0, 0);
  if (view == "side") return view_rotation(90, 0);
  if (view == "top") return view_rotation(0, 90);
  // Two or three numbers separated by commas, nothing else.
  std::vector<double> numbers;
  std::string text(view);
  bool ok = !text.empty();
  for (std::size_t at = 0; ok && at <= text.size();) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string part = text.substr(at, comma - at);
    try {
      std::size_t used = 0;
      numbers.push_back(std::stod(part, &used));
      ok = used == part.size() && std::isfinite(numbers.back());
    } catch (const std::logic_error&) {
      ok = false;
    }
    at = comma + 1;
  }
  if (ok && (numbers.size() == 2 || numbers.size() == 3) && std::fabs(numbers[1]) <= 90)
    return view_rotation(numbers[0], numbers[1], numbers.size() == 3 ? numbers[2] : 0);
  throw InputError(
      "render: view must be front, side, top or AZIMUTH,ELEVATION[,ROLL] in degrees "
      "(elevation within +-90), not '" +
      text + "'");
}

ViewCamera fit_camera(const Vertices& V, const Eigen::Matrix3d& rotation, int x, int y, int w,
                      int h, int margin) {
  ViewCamera camera;
  camera.rotation = rotation;
  Eigen::Vector2d lo(0, 0), hi(0, 0);
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    const Eigen::Vector3d p = rotation * V.row(i).transpose();
    if (i == 0) lo = hi = p.head<2>();
    lo = lo.cwiseMin(p.head<2>()), hi = hi.cwiseMax(p.head<2>());
  }
  const double span_x = std::max(hi.x() - lo.x(), 1e-9), span_y = std::max(hi.y() - lo.y(), 1e-9);
  const double room_x = std::max(w - 2 * margin, 1), room_y = std::max(h - 2 * margin, 1);
  camera.scale = std::min(room_x / span_x, room_y / span_y);
  const Eigen::Vector2d mid = 0.5 * (lo + hi);
  camera.origin_x = x + 0.5 * w - camera.scale * mid.x();
  camera.origin_y = y + 0.5 * h + camera.scale * mid.y();
  return camera;
}

Eigen::Vector3d project(const ViewCamera& camera, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = camera.rotation * p;
  return {camera.origin_x + camera.scale * q.x(), camera.origin_y - camera.scale * q.y(), q.z()};
}

}  // namespace arg
