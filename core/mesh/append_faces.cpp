// Copies the mesh's buffers and the added rows into buffers of the joint size.
#include "mesh/append_faces.hpp"

namespace arg {

Mesh append_faces(const Mesh& mesh, const std::vector<Eigen::RowVector3d>& vertices,
                  const std::vector<Eigen::RowVector3i>& faces,
                  const std::vector<Eigen::RowVector3f>& colours) {
  Mesh out;
  out.V.resize(mesh.V.rows() + Eigen::Index(vertices.size()), 3);
  out.V.topRows(mesh.V.rows()) = mesh.V;
  for (std::size_t k = 0; k < vertices.size(); ++k)
    out.V.row(mesh.V.rows() + Eigen::Index(k)) = vertices[k];
  out.F.resize(mesh.F.rows() + Eigen::Index(faces.size()), 3);
  out.F.topRows(mesh.F.rows()) = mesh.F;
  for (std::size_t k = 0; k < faces.size(); ++k)
    out.F.row(mesh.F.rows() + Eigen::Index(k)) = faces[k];
  if (mesh.has_colour()) {
    out.C.resize(out.F.rows(), 3);
    out.C.topRows(mesh.C.rows()) = mesh.C;
    for (std::size_t k = 0; k < colours.size(); ++k)
      out.C.row(mesh.F.rows() + Eigen::Index(k)) = colours[k];
  }
  return out;
}

}  // namespace arg
