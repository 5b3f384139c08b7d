// An OpenMesh importer that records what the OBJ reader sees in a PolygonSoup, every face kept.
#pragma once

#include <cstddef>
#include <vector>

#include <OpenMesh/Core/IO/importer/BaseImporter.hh>

#include "io/polygon_soup.hpp"

namespace arg::io {

// OpenMesh's own PolyMesh importer drops faces that would make the mesh non-manifold; this one
// keeps them all (the pipeline cleans meshes itself).
class SoupImporter : public OpenMesh::IO::BaseImporter {
 public:
  explicit SoupImporter(SoupBuilder& builder) : builder_(builder) {}

  // The material of each face the reader adds, in call order (an OBJ's f lines), copied to the
  // soup's face_material for the faces it keeps; null: none kept.
  void set_call_materials(const std::vector<int>* materials) { call_materials_ = materials; }

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override;
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override;
  OpenMesh::VertexHandle add_vertex() override;
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(const VHandles& indices) override;
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override {
    return OpenMesh::FaceHandle();
  }
  void add_face_texcoords(OpenMesh::FaceHandle fh, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec2f>& uv) override;
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int) override {}
  void set_point(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& p) override;
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec3uc& c) override;
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec4uc& c) override;
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& c) override;
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec4f& c) override;
  void set_texcoord(OpenMesh::VertexHandle vh, const OpenMesh::Vec2f& t) override;
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec3uc& c) override;
  void set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec4uc& c) override;
  void set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec3f& c) override;
  void set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec4f& c) override;
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

  // Declared counts are untrusted: allocate nothing for them.
  void reserve(unsigned int, unsigned int, unsigned int) override {}

  size_t n_vertices() const override { return builder_.soup().vertex_count(); }
  size_t n_faces() const override { return builder_.soup().face_count(); }
  size_t n_edges() const override { return 0; }

 private:
  SoupBuilder& builder_;
  std::vector<int> scratch_;
  std::vector<float> uv_scratch_;
  const std::vector<int>* call_materials_ = nullptr;
};

}  // namespace arg::io
