// Orthographic cameras on the PCA-aligned frame: named views, fitting a model into a rectangle.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "mesh/mesh.hpp"

namespace arg {

struct ViewCamera {
  // Rows: screen right, screen up, towards the viewer, in model coordinates.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double scale = 1;                   // pixels per model unit
  double origin_x = 0, origin_y = 0;  // where the model's origin lands, in pixels
};

// The aligned frame has its longest principal axis on x, so x is screen up in every view.
// Azimuth turns the viewer about x from +z towards +y; elevation raises it towards +x
// (degrees). front = (0, 0) looks along the smallest axis and shows the two largest;
// side = (90, 0); top = (0, 90). Roll then turns the picture clockwise about the view
// direction (180 turns a model upside down).
Eigen::Matrix3d view_rotation(double azimuth_degrees, double elevation_degrees,
                              double roll_degrees = 0);

// "front", "side", "top" or "AZIMUTH,ELEVATION[,ROLL]" in degrees; throws InputError otherwise.
Eigen::Matrix3d parse_view(std::string_view view);

// Scales and centres the projection of `V` to fill the rectangle (x, y, w, h), `margin` pixels
// inside each side.
ViewCamera fit_camera(const Vertices& V, const Eigen::Matrix3d& rotation, int x, int y, int w,
                      int h, int margin);

// (pixel x, pixel y growing downwards, depth growing towards the viewer). Pixel (i, j) covers
// [i, i + 1) x [j, j + 1).
Eigen::Vector3d project(const ViewCamera& camera, const Eigen::Vector3d& p);

}  // namespace arg
