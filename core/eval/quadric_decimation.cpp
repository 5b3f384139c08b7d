// Quadric decimation through OpenMesh's decimater: a well-kept implementation of a solved problem.
#include "eval/quadric_decimation.hpp"

#include <array>
#include <mutex>
#include <vector>

// OpenMesh's property arrays push default-constructed points, whose coordinates GCC 12 sees as
// possibly uninitialised once inlined here; they are assigned before use.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include "mesh/coincident_vertices.hpp"

namespace arg {
namespace {

struct Traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
};
using HalfedgeMesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;
using Vertex = HalfedgeMesh::VertexHandle;

// A face OpenMesh refuses reports on its error stream, read by no one here. (Threads that
// decimate at once still write to that one disabled stream: harmless, the text goes nowhere.)
void silence_openmesh() {
  static std::once_flag once;
  std::call_once(once, [] {
    ::omerr().disable();
    ::omlog().disable();
    ::omout().disable();
  });
}

}  // namespace

Mesh quadric_decimation(const Mesh& mesh, std::size_t target_vertices) {
  silence_openmesh();
  HalfedgeMesh hm;
  // One vertex per distinct position (mesh/coincident_vertices.hpp), in order of first use by a
  // face.
  const std::vector<int> first = first_at_same_position(mesh);
  std::vector<Vertex> handle(std::size_t(mesh.V.rows()));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.F(f, c), at = first[std::size_t(v)];
      if (!handle[std::size_t(at)].is_valid())
        handle[std::size_t(at)] =
            hm.add_vertex(HalfedgeMesh::Point(mesh.V(at, 0), mesh.V(at, 1), mesh.V(at, 2)));
      handle[std::size_t(v)] = handle[std::size_t(at)];
    }
  // Faces the halfedge structure cannot hold, and faces with a repeated corner, stay as given.
  std::vector<std::array<Eigen::RowVector3d, 3>> aside;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Vertex a = handle[std::size_t(mesh.F(f, 0))], b = handle[std::size_t(mesh.F(f, 1))],
                 c = handle[std::size_t(mesh.F(f, 2))];
    if (a == b || b == c || a == c || !hm.add_face(a, b, c).is_valid())
      aside.push_back(
          {mesh.V.row(mesh.F(f, 0)), mesh.V.row(mesh.F(f, 1)), mesh.V.row(mesh.F(f, 2))});
  }
  // Corners only set-aside faces used are not points of the surface to decimate: the budget
  // counts the others.
  for (const auto vh : hm.vertices())
    if (hm.is_isolated(vh)) hm.delete_vertex(vh, false);
  hm.garbage_collection();
  hm.update_face_normals();
  {
    OpenMesh::Decimater::DecimaterT<HalfedgeMesh> decimater(hm);
    OpenMesh::Decimater::ModQuadricT<HalfedgeMesh>::Handle quadric;
    OpenMesh::Decimater::ModNormalFlippingT<HalfedgeMesh>::Handle no_flips;
    decimater.add(quadric);
    decimater.add(no_flips);
    decimater.module(quadric).unset_max_err();  // the vertex budget decides, not an error bound
    if (decimater.initialize()) decimater.decimate_to(target_vertices);
  }
  hm.garbage_collection();

  // Back to plain arrays: the kept vertices that a face uses, then the faces set aside.
  Mesh out;
  std::vector<int> id(hm.n_vertices(), -1);
  std::vector<Eigen::RowVector3d> points;
  std::vector<std::array<int, 3>> faces;
  for (const auto fh : hm.faces()) {
    std::array<int, 3> face{};
    int k = 0;
    for (const auto vh : hm.fv_range(fh)) {
      int& slot = id[std::size_t(vh.idx())];
      if (slot < 0) {
        slot = int(points.size());
        const auto& p = hm.point(vh);
        points.emplace_back(p[0], p[1], p[2]);
      }
      face[std::size_t(k++)] = slot;
    }
    faces.push_back(face);
  }
  for (const auto& corners : aside) {
    const int first = int(points.size());
    for (const auto& p : corners) points.push_back(p);
    faces.push_back({first, first + 1, first + 2});
  }
  out.V.resize(Eigen::Index(points.size()), 3);
  for (std::size_t k = 0; k < points.size(); ++k) out.V.row(Eigen::Index(k)) = points[k];
  out.F.resize(Eigen::Index(faces.size()), 3);
  for (std::size_t k = 0; k < faces.size(); ++k)
    for (int c = 0; c < 3; ++c) out.F(Eigen::Index(k), c) = faces[k][std::size_t(c)];
  return out;
}

}  // namespace arg
