// Writing a mesh to bytes in the common exchange formats, deterministically.
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace arg {

// ASCII OFF. Coordinates with 9 significant digits (enough to restore a float exactly),
// independent of the C locale. With colour, each face line carries it as integers 0..255
// ("3 i j k r g b"), which Geomview's OFF allows without a C in the keyword (a C would announce
// vertex colours).
std::string write_off(const Mesh& mesh);

// Binary little-endian PLY with float coordinates, int indices and, with colour, uchar
// red/green/blue per face.
std::string write_ply_binary(const Mesh& mesh);

// Binary STL: float coordinates and unit facet normals; STL has no place for colour.
std::string write_stl_binary(const Mesh& mesh);

// Wavefront OBJ, vertices and triangles only (per-face colour would need a material file).
std::string write_obj(const Mesh& mesh);

}  // namespace arg
