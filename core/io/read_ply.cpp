// Reading PLY meshes (ASCII and binary, every element layout) with a parser of our own.
//
// Not OpenMesh's reader: OpenMesh 9.0 reads only part of what PLY allows and misreads the rest
// without an error. It skips "tristrips" (range scans, igea.ply) and leaves the mesh without
// faces; skips list properties other than the face's indices as one scalar, shifting everything
// after them (MeshLab's per-corner "texcoord"); reads integer coordinates and double colours as 0;
// refuses list lengths other than uchar/uint16/int; stops after the face element; and finds a
// binary body by counting back from "end_header", which a comment line throws off. This parser
// walks the header's layout value by value with bounds checks and names the byte or line of every
// error; ASCII floats are rounded as the declared type says, as binary floats are stored.
#include <cmath>
#include <string>
#include <vector>

#include "io/format_readers.hpp"
#include "io/ply_body.hpp"

namespace arg::io {

namespace {

enum class Role { Skip, X, Y, Z, Red, Green, Blue, U, V, Indices, Strip, CornerUv };

Role role_of(const PlyElement& e, const PlyProperty& p) {
  const std::string& n = p.name;
  if (e.name == "vertex" && !p.is_list) {
    if (n == "x") return Role::X;
    if (n == "y") return Role::Y;
    if (n == "z") return Role::Z;
    if (n == "red" || n == "diffuse_red") return Role::Red;
    if (n == "green" || n == "diffuse_green") return Role::Green;
    if (n == "blue" || n == "diffuse_blue") return Role::Blue;
    if (n == "u" || n == "s" || n == "texture_u" || n == "texture_s") return Role::U;
    if (n == "v" || n == "t" || n == "texture_v" || n == "texture_t") return Role::V;
  } else if (e.name == "face") {
    if (p.is_list && (n == "vertex_indices" || n == "vertex_index")) return Role::Indices;
    if (p.is_list && n == "texcoord") return Role::CornerUv;
    if (!p.is_list && n == "red") return Role::Red;
    if (!p.is_list && n == "green") return Role::Green;
    if (!p.is_list && n == "blue") return Role::Blue;
  } else if (e.name == "tristrips") {
    if (p.is_list && (n == "vertex_indices" || n == "vertex_index")) return Role::Strip;
  }
  return Role::Skip;
}

// Colour channels: floats are in [0,1]; integers are 0..255 (8-bit) or 0..65535 (16-bit).
float channel(double value, PlyType type) {
  if (!ply_type_is_integer(type)) return static_cast<float>(value);
  const std::size_t size = ply_type_size(type);
  return static_cast<float>(value / (size == 2 ? 65535.0 : 255.0));
}

int vertex_index(PlyBodyCursor& cursor, double value, std::size_t element, bool allow_minus_one) {
  if (value != std::floor(value) || value < (allow_minus_one ? -1 : 0) || value > 2147483647.0) {
    cursor.fail("element " + std::to_string(element) + " has an invalid vertex index " +
                std::to_string(value));
  }
  return static_cast<int>(value);
}

}  // namespace

// Vertex x/y/z with optional colour and texture coordinates, face lists with optional colour
// and per-corner "texcoord" lists, and "tristrips" (strips separated by -1, alternate triangles
// wound the other way, degenerate joining triangles dropped); other elements are skipped.
void read_ply(std::string_view bytes, SoupBuilder& out, ReadReport& report) {
  const PlyHeader header = parse_ply_header(bytes);
  report.variant = ply_encoding_name(header.encoding);
  check_ply_declared_counts(bytes, header, out);
  PlyBodyCursor cursor(bytes, header);
  out.set_locator([&] { return cursor.where(); });
  const PlyElement* vertex = header.find("vertex");
  if (!vertex) throw_input_error("PLY", "", "no vertex element");
  // Indices stored before the vertices are checked at the end; otherwise at once, with a place.
  const PlyElement* face = header.find("face");
  const PlyElement* strips = header.find("tristrips");
  out.set_immediate_index_check((!face || vertex < face) && (!strips || vertex < strips));
  int xyz = 0;
  for (const PlyProperty& p : vertex->properties) {
    const Role r = role_of(*vertex, p);
    xyz += r == Role::X || r == Role::Y || r == Role::Z;
  }
  if (xyz != 3) throw_input_error("PLY", "", "the vertex element needs x, y and z");
  if (header.find("tristrips")) report.variant += ", triangle strips";

  std::vector<int> corners;
  std::vector<float> uv;
  std::vector<int> strip;
  for (const PlyElement& e : header.elements) {
    // Each property's role once an element, not once a vertex: the names' comparisons were a
    // fifth of reading a binary PLY.
    std::vector<Role> roles;
    for (const PlyProperty& prop : e.properties) roles.push_back(role_of(e, prop));
    for (std::uint64_t i = 0; i < e.count; ++i) {
      double p[3] = {0, 0, 0};
      float rgb[3] = {0, 0, 0};
      float st[2] = {0, 0};
      bool has_rgb = false, has_st = false;
      corners.clear();
      uv.clear();
      for (std::size_t at = 0; at < e.properties.size(); ++at) {
        const PlyProperty& prop = e.properties[at];
        const Role role = roles[at];
        if (prop.is_list) {
          const std::size_t n = cursor.read_count(prop.count_type, prop.type);
          if (role == Role::Skip) {
            for (std::size_t k = 0; k < n; ++k) cursor.skip(prop.type);
            continue;
          }
          if (role == Role::Indices && n > out.limits().max_triangles + 2) {
            out.fail_limit("face " + std::to_string(i) + " has " + std::to_string(n) +
                           " corners, more than the triangle limit allows");
          }
          std::vector<int>& target = role == Role::Strip ? strip : corners;
          if (role != Role::CornerUv) target.clear();
          for (std::size_t k = 0; k < n; ++k) {
            const double value = cursor.read(prop.type);
            if (role == Role::CornerUv) {
              uv.push_back(static_cast<float>(value));
            } else {
              target.push_back(vertex_index(cursor, value, i, role == Role::Strip));
            }
          }
          continue;
        }
        const double value = cursor.read(prop.type);
        switch (role) {
          case Role::X:
            p[0] = value;
            break;
          case Role::Y:
            p[1] = value;
            break;
          case Role::Z:
            p[2] = value;
            break;
          case Role::Red:
          case Role::Green:
          case Role::Blue:
            rgb[role == Role::Red ? 0 : role == Role::Green ? 1 : 2] = channel(value, prop.type);
            has_rgb = true;
            break;
          case Role::U:
          case Role::V:
            st[role == Role::U ? 0 : 1] = static_cast<float>(value);
            has_st = true;
            break;
          default:
            break;
        }
      }
      if (e.name == "vertex") {
        const int v = out.add_vertex(p[0], p[1], p[2]);
        if (has_rgb) out.set_vertex_colour(v, rgb[0], rgb[1], rgb[2]);
        if (has_st) out.set_vertex_uv(v, st[0], st[1]);
      } else if (e.name == "face") {
        const int f = out.add_face(corners.data(), corners.size());
        if (f >= 0 && has_rgb) out.set_face_colour(f, rgb[0], rgb[1], rgb[2]);
        if (f >= 0 && uv.size() == 2 * corners.size()) {
          out.set_corner_uvs(f, uv.data(), corners.size());
        }
      } else if (e.name == "tristrips") {
        std::size_t run = 0;  // length of the current strip so far
        for (std::size_t k = 0; k < strip.size(); ++k) {
          if (strip[k] < 0) {
            run = 0;
            continue;
          }
          if (++run < 3) continue;
          int t[3] = {strip[k - 2], strip[k - 1], strip[k]};
          if ((run - 3) % 2 == 1) std::swap(t[0], t[1]);
          if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
          out.add_face(t, 3);
        }
      } else {
        out.poll();
      }
    }
  }
  out.set_locator({});
  out.check_indices();
}

}  // namespace arg::io
