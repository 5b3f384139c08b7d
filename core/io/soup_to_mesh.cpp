// Turning a polygon soup into the pipeline's triangle mesh, with one colour per triangle.
#include "io/soup_to_mesh.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "io/triangulate_polygon.hpp"

namespace arg::io {

namespace {

bool all_finite(const std::vector<float>& values, std::size_t begin, std::size_t count) {
  for (std::size_t i = begin; i < begin + count; ++i) {
    if (!std::isfinite(values[i])) return false;
  }
  return true;
}

enum class Colour { None, Texture, Face, Vertex };

// The texture coordinates of the triangle whose corners are the soup's corner slots `s`: per
// corner when all three have them, else per vertex; false when neither is complete.
bool triangle_uv_of(const PolygonSoup& soup, const std::array<std::size_t, 3>& s, double uv[3][2]) {
  bool have = !soup.corner_uv.empty();
  for (std::size_t c = 0; c < 3 && have; ++c) {
    have = all_finite(soup.corner_uv, 2 * s[c], 2);
    if (have) {
      uv[c][0] = soup.corner_uv[2 * s[c]];
      uv[c][1] = soup.corner_uv[2 * s[c] + 1];
    }
  }
  if (!have && !soup.vertex_uv.empty()) {
    have = true;
    for (std::size_t c = 0; c < 3 && have; ++c) {
      const std::size_t v = std::size_t(soup.corners[s[c]]);
      have = all_finite(soup.vertex_uv, 2 * v, 2);
      if (have) {
        uv[c][0] = soup.vertex_uv[2 * v];
        uv[c][1] = soup.vertex_uv[2 * v + 1];
      }
    }
  }
  return have;
}

}  // namespace

bool soup_has_texture_coordinates(const PolygonSoup& soup) {
  return !soup.corner_uv.empty() || !soup.vertex_uv.empty();
}

Mesh soup_to_mesh(const PolygonSoup& soup, const Image* texture, const TextureSampler& sampler,
                  SoupBuilder& out, ReadReport& report, std::vector<float>* triangle_uv,
                  std::vector<int>* triangle_face) {
  const std::size_t nv = soup.vertex_count();
  const std::size_t nf = soup.face_count();

  // Faces without repeated neighbouring corners, triangulated.
  std::vector<int> face_of;                       // per triangle
  std::vector<std::array<std::size_t, 3>> slots;  // per triangle: corner slots into soup.corners
  std::vector<std::array<std::size_t, 3>> local;
  std::vector<int> ring;
  std::vector<std::size_t> ring_slot;
  std::size_t skipped = soup.faces_skipped;
  std::size_t ear_clipping_budget = std::size_t(200) * 1000 * 1000;
  for (std::size_t f = 0; f < nf; ++f) {
    out.poll();
    ring.clear();
    ring_slot.clear();
    for (std::size_t k = soup.face_begin[f]; k < soup.face_begin[f + 1]; ++k) {
      if (!ring.empty() && ring.back() == soup.corners[k]) continue;
      ring.push_back(soup.corners[k]);
      ring_slot.push_back(k);
    }
    while (ring.size() > 1 && ring.front() == ring.back()) {
      ring.pop_back();
      ring_slot.pop_back();
    }
    if (ring.size() < 3) {
      ++skipped;
      continue;
    }
    if (ring.size() > 3) ++report.polygons_triangulated;
    local.clear();
    triangulate_polygon(soup.xyz.data(), ring.data(), ring.size(), local, ear_clipping_budget);
    for (const auto& t : local) {
      face_of.push_back(static_cast<int>(f));
      slots.push_back({ring_slot[t[0]], ring_slot[t[1]], ring_slot[t[2]]});
    }
  }
  report.faces_skipped = skipped;
  if (slots.empty()) throw_input_error(out.format(), "", "the mesh has no faces");

  Mesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(nv), 3);
  for (std::size_t v = 0; v < nv; ++v) {
    for (int c = 0; c < 3; ++c) mesh.V(Eigen::Index(v), c) = soup.xyz[3 * v + std::size_t(c)];
  }
  const Eigen::Index nt = static_cast<Eigen::Index>(slots.size());
  mesh.F.resize(nt, 3);
  for (Eigen::Index t = 0; t < nt; ++t) {
    for (int c = 0; c < 3; ++c) mesh.F(t, c) = soup.corners[slots[std::size_t(t)][std::size_t(c)]];
  }
  report.triangles = slots.size();
  if (triangle_face) *triangle_face = face_of;
  if (triangle_uv) {
    triangle_uv->assign(6 * slots.size(), std::numeric_limits<float>::quiet_NaN());
    if (soup_has_texture_coordinates(soup)) {
      for (std::size_t t = 0; t < slots.size(); ++t) {
        double uv[3][2];
        if (!triangle_uv_of(soup, slots[t], uv)) continue;
        for (std::size_t i = 0; i < 6; ++i) (*triangle_uv)[6 * t + i] = float(uv[i / 2][i % 2]);
      }
    }
  }

  // Which colour source is complete enough to use.
  Colour colour = Colour::None;
  if (texture && !texture->empty() && soup_has_texture_coordinates(soup)) {
    colour = Colour::Texture;
  } else if (!soup.face_rgb.empty() && all_finite(soup.face_rgb, 0, soup.face_rgb.size())) {
    colour = Colour::Face;
  } else if (!soup.vertex_rgb.empty()) {
    bool complete = true;
    for (std::size_t t = 0; t < slots.size() && complete; ++t) {
      for (std::size_t c = 0; c < 3 && complete; ++c) {
        complete = all_finite(soup.vertex_rgb, 3 * std::size_t(soup.corners[slots[t][c]]), 3);
      }
    }
    if (complete) {
      colour = Colour::Vertex;
    } else {
      report.warnings.push_back("vertex colours ignored: not every vertex has one");
    }
  }
  if (colour == Colour::None) {
    report.colour_source = "none";
    return mesh;
  }
  mesh.C.resize(nt, 3);
  std::array<float, 3> fallback{0, 0, 0};
  bool used_fallback = false;
  if (colour == Colour::Texture) fallback = mean_texture_colour(*texture);
  for (Eigen::Index t = 0; t < nt; ++t) {
    const auto& s = slots[std::size_t(t)];
    std::array<float, 3> rgb{0, 0, 0};
    if (colour == Colour::Texture) {
      double uv[3][2];
      if (triangle_uv_of(soup, s, uv)) {
        rgb = triangle_texture_colour(*texture, uv, sampler);
      } else {
        rgb = fallback;
        used_fallback = true;
      }
    } else if (colour == Colour::Face) {
      const std::size_t f = std::size_t(face_of[std::size_t(t)]);
      rgb = {soup.face_rgb[3 * f], soup.face_rgb[3 * f + 1], soup.face_rgb[3 * f + 2]};
    } else {
      for (std::size_t c = 0; c < 3; ++c) {
        const std::size_t v = std::size_t(soup.corners[s[c]]);
        for (std::size_t i = 0; i < 3; ++i) rgb[i] += soup.vertex_rgb[3 * v + i] / 3.0f;
      }
    }
    for (int i = 0; i < 3; ++i) mesh.C(t, i) = rgb[std::size_t(i)];
  }
  if (used_fallback) {
    report.warnings.push_back(
        "some faces have no texture coordinates; they take the texture's mean colour");
  }
  report.colour_source = colour == Colour::Texture ? "texture"
                         : colour == Colour::Face  ? soup.face_colour_source
                                                   : "vertex";
  return mesh;
}

}  // namespace arg::io
