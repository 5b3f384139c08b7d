// An OpenMesh importer that records what the OBJ reader sees in a PolygonSoup, every face kept.
#include "io/soup_importer.hpp"

namespace arg::io {

namespace {
constexpr float kByte = 1.0f / 255.0f;
}

OpenMesh::VertexHandle SoupImporter::add_vertex(const OpenMesh::Vec3f& p) {
  return OpenMesh::VertexHandle(builder_.add_vertex(p[0], p[1], p[2]));
}

OpenMesh::VertexHandle SoupImporter::add_vertex(const OpenMesh::Vec3d& p) {
  return OpenMesh::VertexHandle(builder_.add_vertex(p[0], p[1], p[2]));
}

OpenMesh::VertexHandle SoupImporter::add_vertex() {
  return OpenMesh::VertexHandle(builder_.add_vertex_unset());
}

void SoupImporter::set_point(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& p) {
  builder_.set_vertex(vh.idx(), p[0], p[1], p[2]);
}

OpenMesh::FaceHandle SoupImporter::add_face(const VHandles& indices) {
  scratch_.resize(indices.size());
  for (std::size_t i = 0; i < indices.size(); ++i) scratch_[i] = indices[i].idx();
  const std::size_t call = builder_.soup().faces_seen;  // add_face counts every call
  const int face = builder_.add_face(scratch_.data(), scratch_.size());
  if (call_materials_ && face >= 0) {
    builder_.soup().face_material.push_back(
        call < call_materials_->size() ? (*call_materials_)[call] : -1);
  }
  return OpenMesh::FaceHandle(face);
}

void SoupImporter::add_face_texcoords(OpenMesh::FaceHandle fh, OpenMesh::VertexHandle,
                                      const std::vector<OpenMesh::Vec2f>& uv) {
  if (!fh.is_valid() || uv.empty()) return;
  uv_scratch_.resize(2 * uv.size());
  for (std::size_t i = 0; i < uv.size(); ++i) {
    uv_scratch_[2 * i] = uv[i][0];
    uv_scratch_[2 * i + 1] = uv[i][1];
  }
  builder_.set_corner_uvs(fh.idx(), uv_scratch_.data(), uv.size());
}

void SoupImporter::set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec3uc& c) {
  builder_.set_vertex_colour(vh.idx(), c[0] * kByte, c[1] * kByte, c[2] * kByte);
}
void SoupImporter::set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec4uc& c) {
  builder_.set_vertex_colour(vh.idx(), c[0] * kByte, c[1] * kByte, c[2] * kByte);
}
void SoupImporter::set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& c) {
  builder_.set_vertex_colour(vh.idx(), c[0], c[1], c[2]);
}
void SoupImporter::set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec4f& c) {
  builder_.set_vertex_colour(vh.idx(), c[0], c[1], c[2]);
}
void SoupImporter::set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec3uc& c) {
  builder_.set_face_colour(fh.idx(), c[0] * kByte, c[1] * kByte, c[2] * kByte);
}
void SoupImporter::set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec4uc& c) {
  builder_.set_face_colour(fh.idx(), c[0] * kByte, c[1] * kByte, c[2] * kByte);
}
void SoupImporter::set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec3f& c) {
  builder_.set_face_colour(fh.idx(), c[0], c[1], c[2]);
}
void SoupImporter::set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec4f& c) {
  builder_.set_face_colour(fh.idx(), c[0], c[1], c[2]);
}

void SoupImporter::set_texcoord(OpenMesh::VertexHandle vh, const OpenMesh::Vec2f& t) {
  builder_.set_vertex_uv(vh.idx(), t[0], t[1]);
}

}  // namespace arg::io
