// The polygon soup every mesh reader fills before triangulation, and the builder that checks it.
#include "io/polygon_soup.hpp"

#include <cmath>
#include <limits>

#include "common/errors.hpp"

namespace arg::io {

namespace {

constexpr float kUnset = std::numeric_limits<float>::quiet_NaN();

bool finite3(double x, double y, double z) {
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

float unit(float c) {
  return std::isfinite(c) ? std::fmin(1.0f, std::fmax(0.0f, c)) : 0.0f;
}

}  // namespace

void throw_input_error(const std::string& format, const std::string& where,
                       const std::string& message) {
  throw InputError(format + ": " + (where.empty() ? "" : where + ": ") + message);
}

SoupBuilder::SoupBuilder(PolygonSoup& soup, std::string format, const Limits& limits,
                         const StopRequested& stop)
    : soup_(soup), format_(std::move(format)), limits_(limits), stop_(stop) {}

std::string SoupBuilder::where() const {
  return locate_ ? locate_() : std::string();
}

void SoupBuilder::fail(const std::string& message) const {
  throw_input_error(format_, where(), message);
}

void SoupBuilder::fail_limit(const std::string& message) const {
  throw LimitError(format_ + ": " + message);
}

void SoupBuilder::poll() {
  if ((++ticks_ & 4095u) == 0) check_interrupt(stop_);
}

int SoupBuilder::add_vertex_unset() {
  const std::size_t n = soup_.vertex_count();
  if (n >= limits_.max_vertices || n >= static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    fail_limit("more than " + std::to_string(limits_.max_vertices) + " vertices");
  }
  poll();
  soup_.xyz.insert(soup_.xyz.end(), {0.0, 0.0, 0.0});
  if (!soup_.vertex_rgb.empty()) soup_.vertex_rgb.insert(soup_.vertex_rgb.end(), 3, kUnset);
  if (!soup_.vertex_uv.empty()) soup_.vertex_uv.insert(soup_.vertex_uv.end(), 2, kUnset);
  return static_cast<int>(n);
}

int SoupBuilder::add_vertex(double x, double y, double z) {
  const int v = add_vertex_unset();
  set_vertex(v, x, y, z);
  return v;
}

void SoupBuilder::set_vertex(int v, double x, double y, double z) {
  if (v < 0 || static_cast<std::size_t>(v) >= soup_.vertex_count()) return;
  if (!finite3(x, y, z)) {
    fail("vertex " + std::to_string(v) + " has a coordinate that is not a finite number");
  }
  double* p = &soup_.xyz[3 * static_cast<std::size_t>(v)];
  p[0] = x;
  p[1] = y;
  p[2] = z;
}

int SoupBuilder::add_face(const int* indices, std::size_t count) {
  const std::size_t face_number = soup_.faces_seen++;
  poll();
  if (immediate_index_check_) {
    const std::size_t nv = soup_.vertex_count();
    for (std::size_t i = 0; i < count; ++i) {
      if (indices[i] < 0 || static_cast<std::size_t>(indices[i]) >= nv) {
        fail("face " + std::to_string(face_number) + " refers to vertex " +
             std::to_string(indices[i]) + " but there are " + std::to_string(nv) + " vertices");
      }
    }
  }
  if (count < 3) {
    ++soup_.faces_skipped;
    return -1;
  }
  triangles_ += count - 2;
  if (triangles_ > limits_.max_triangles ||
      soup_.face_count() >= static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    fail_limit("more than " + std::to_string(limits_.max_triangles) + " triangles");
  }
  soup_.corners.insert(soup_.corners.end(), indices, indices + count);
  soup_.face_begin.push_back(soup_.corners.size());
  if (!soup_.face_rgb.empty()) soup_.face_rgb.insert(soup_.face_rgb.end(), 3, kUnset);
  if (!soup_.corner_uv.empty()) soup_.corner_uv.insert(soup_.corner_uv.end(), 2 * count, kUnset);
  return static_cast<int>(soup_.face_count() - 1);
}

void SoupBuilder::set_vertex_colour(int v, float r, float g, float b) {
  if (v < 0 || static_cast<std::size_t>(v) >= soup_.vertex_count()) return;
  if (soup_.vertex_rgb.empty()) soup_.vertex_rgb.assign(3 * soup_.vertex_count(), kUnset);
  float* c = &soup_.vertex_rgb[3 * static_cast<std::size_t>(v)];
  c[0] = unit(r);
  c[1] = unit(g);
  c[2] = unit(b);
}

void SoupBuilder::set_face_colour(int f, float r, float g, float b) {
  if (f < 0 || static_cast<std::size_t>(f) >= soup_.face_count()) return;
  if (soup_.face_rgb.empty()) soup_.face_rgb.assign(3 * soup_.face_count(), kUnset);
  float* c = &soup_.face_rgb[3 * static_cast<std::size_t>(f)];
  c[0] = unit(r);
  c[1] = unit(g);
  c[2] = unit(b);
}

void SoupBuilder::set_vertex_uv(int v, float s, float t) {
  if (v < 0 || static_cast<std::size_t>(v) >= soup_.vertex_count()) return;
  if (!std::isfinite(s) || !std::isfinite(t)) {
    fail("vertex " + std::to_string(v) + " has a texture coordinate that is not finite");
  }
  if (soup_.vertex_uv.empty()) soup_.vertex_uv.assign(2 * soup_.vertex_count(), kUnset);
  soup_.vertex_uv[2 * static_cast<std::size_t>(v)] = s;
  soup_.vertex_uv[2 * static_cast<std::size_t>(v) + 1] = t;
}

void SoupBuilder::set_corner_uvs(int f, const float* uv, std::size_t count) {
  if (f < 0 || static_cast<std::size_t>(f) >= soup_.face_count()) return;
  const std::size_t begin = soup_.face_begin[static_cast<std::size_t>(f)];
  const std::size_t end = soup_.face_begin[static_cast<std::size_t>(f) + 1];
  if (count != end - begin) return;
  for (std::size_t i = 0; i < 2 * count; ++i) {
    if (!std::isfinite(uv[i])) {
      fail("face " + std::to_string(f) + " has a texture coordinate that is not finite");
    }
  }
  if (soup_.corner_uv.empty()) soup_.corner_uv.assign(2 * soup_.corners.size(), kUnset);
  std::copy(uv, uv + 2 * count, soup_.corner_uv.begin() + static_cast<std::ptrdiff_t>(2 * begin));
}

void SoupBuilder::check_indices() const {
  const std::size_t nv = soup_.vertex_count();
  for (std::size_t f = 0; f < soup_.face_count(); ++f) {
    for (std::size_t k = soup_.face_begin[f]; k < soup_.face_begin[f + 1]; ++k) {
      const int v = soup_.corners[k];
      if (v < 0 || static_cast<std::size_t>(v) >= nv) {
        throw_input_error(format_, "",
                          "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                              " but there are " + std::to_string(nv) + " vertices");
      }
    }
  }
}

void check_declared_counts(SoupBuilder& out, std::size_t vertices, std::size_t faces,
                           std::size_t min_vertex_bytes, std::size_t min_face_bytes,
                           std::size_t left) {
  // Compare in floating point so that absurd counts cannot overflow.
  if (double(vertices) * double(min_vertex_bytes) + double(faces) * double(min_face_bytes) >
      double(left) + 1.0) {
    out.fail("header declares " + std::to_string(vertices) + " vertices and " +
             std::to_string(faces) + " faces but only " + std::to_string(left) + " bytes follow");
  }
  if (vertices > out.limits().max_vertices) {
    out.fail_limit("header declares " + std::to_string(vertices) + " vertices, more than " +
                   std::to_string(out.limits().max_vertices));
  }
  if (faces > out.limits().max_triangles) {
    out.fail_limit("header declares " + std::to_string(faces) + " faces, more than " +
                   std::to_string(out.limits().max_triangles) + " triangles");
  }
  out.declared_counts(vertices, faces);
}

}  // namespace arg::io
