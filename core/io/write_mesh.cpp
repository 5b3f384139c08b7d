// Writing a mesh to bytes in the common exchange formats, deterministically.
#include "common/strict_fp.hpp"  // first: STL normals must not depend on FMA contraction

#include "io/write_mesh.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace arg {
namespace {

// %.9g without the C locale's say on the decimal point.
void append_real(std::string& out, double value) {
  char buffer[32];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 9);
  out.append(buffer, result.ptr);
}

void append_int(std::string& out, long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

int colour_byte(float c) {
  return static_cast<int>(std::lround(std::clamp(static_cast<double>(c), 0.0, 1.0) * 255.0));
}

// Little-endian bytes whatever the host's order.
void append_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

void append_f32(std::string& out, double value) {
  const float f = static_cast<float>(value);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  append_u32(out, bits);
}

void append_vertex_line(std::string& out, const char* prefix, const Mesh& mesh, Eigen::Index v) {
  out += prefix;
  for (int c = 0; c < 3; ++c) {
    if (c > 0) out += ' ';
    append_real(out, mesh.V(v, c));
  }
  out += '\n';
}

}  // namespace

std::string write_off(const Mesh& mesh) {
  const bool colour = mesh.has_colour();
  std::string out = "OFF\n";
  append_int(out, mesh.V.rows());
  out += ' ';
  append_int(out, mesh.F.rows());
  out += " 0\n";
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) append_vertex_line(out, "", mesh, v);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    out += '3';
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      append_int(out, mesh.F(f, c));
    }
    if (colour)
      for (int c = 0; c < 3; ++c) {
        out += ' ';
        append_int(out, colour_byte(mesh.C(f, c)));
      }
    out += '\n';
  }
  return out;
}

std::string write_ply_binary(const Mesh& mesh) {
  const bool colour = mesh.has_colour();
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by arg\nelement vertex ";
  append_int(out, mesh.V.rows());
  out += "\nproperty float x\nproperty float y\nproperty float z\nelement face ";
  append_int(out, mesh.F.rows());
  out += "\nproperty list uchar int vertex_indices\n";
  if (colour) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out += "end_header\n";
  out.reserve(out.size() + static_cast<std::size_t>(mesh.V.rows()) * 12 +
              static_cast<std::size_t>(mesh.F.rows()) * (colour ? 16 : 13));
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    for (int c = 0; c < 3; ++c) append_f32(out, mesh.V(v, c));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    out.push_back(3);
    for (int c = 0; c < 3; ++c) append_u32(out, static_cast<std::uint32_t>(mesh.F(f, c)));
    if (colour)
      for (int c = 0; c < 3; ++c) out.push_back(static_cast<char>(colour_byte(mesh.C(f, c))));
  }
  return out;
}

std::string write_stl_binary(const Mesh& mesh) {
  // The 80-byte header must not begin with "solid", or readers take the file for ASCII STL.
  std::string out = "binary STL written by arg";
  out.resize(80, ' ');
  append_u32(out, static_cast<std::uint32_t>(mesh.F.rows()));
  out.reserve(84 + static_cast<std::size_t>(mesh.F.rows()) * 50);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)),
                          c = mesh.V.row(mesh.F(f, 2));
    const Eigen::Vector3d e1 = b - a, e2 = c - a;
    // Spelled out rather than Eigen's cross/norm so every platform rounds the same way.
    double n[3] = {e1.y() * e2.z() - e1.z() * e2.y(), e1.z() * e2.x() - e1.x() * e2.z(),
                   e1.x() * e2.y() - e1.y() * e2.x()};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) {
      x = len > 0 ? x / len : 0.0;
      append_f32(out, x);
    }
    for (const Eigen::Vector3d* p : {&a, &b, &c})
      for (int k = 0; k < 3; ++k) append_f32(out, (*p)[k]);
    out.push_back(0);
    out.push_back(0);
  }
  return out;
}

std::string write_obj(const Mesh& mesh) {
  std::string out = "# written by arg\n";
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) append_vertex_line(out, "v ", mesh, v);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    out += 'f';
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      append_int(out, static_cast<long long>(mesh.F(f, c)) + 1);
    }
    out += '\n';
  }
  return out;
}

}  // namespace arg
