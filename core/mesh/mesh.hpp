// The triangle mesh every stage of the pipeline works on: plain index buffers.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products are defined here

namespace arg {

using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
// Per-triangle RGB in [0,1]; zero rows when the mesh carries no colour.
using FaceColours = Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct Mesh {
  Vertices V;
  Triangles F;
  FaceColours C;

  bool has_colour() const { return C.rows() == F.rows() && F.rows() > 0; }
};

}  // namespace arg
