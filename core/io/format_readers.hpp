// The per-format readers behind read_mesh: bytes in, polygon soup out (internal to core/io).
#pragma once

#include <string_view>

#include "io/off_header.hpp"
#include "io/ply_header.hpp"
#include "io/polygon_soup.hpp"
#include "io/read_mesh.hpp"

namespace arg::io {

// Each reader fills `out` (whose format name prefixes every error) and the variant/warnings of
// `report`; read_mesh does the triangulation, colouring and the rest of the report.
void read_off(std::string_view bytes, SoupBuilder& out, ReadReport& report);
void read_off_binary(std::string_view bytes, const OffHeader& header, SoupBuilder& out,
                     ReadReport& report);
void read_obj(std::string_view bytes, SoupBuilder& out, ReadReport& report);
void read_ply(std::string_view bytes, SoupBuilder& out, ReadReport& report);
void read_stl(std::string_view bytes, SoupBuilder& out, ReadReport& report);
void read_stl_ascii(std::string_view bytes, SoupBuilder& out, ReadReport& report);
void read_glb(std::string_view bytes, SoupBuilder& out, ReadReport& report);

// True when `bytes` has the exact size a binary STL with the triangle count at offset 80 has.
bool stl_binary_size_matches(std::string_view bytes);

}  // namespace arg::io
