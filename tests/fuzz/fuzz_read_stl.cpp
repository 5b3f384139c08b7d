// libFuzzer target: read_mesh with the format forced to STL, checking the mesh it returns.
#include "fuzz_support.hpp"

namespace arg::fuzz {

inline int fuzz_read_stl(const std::uint8_t* data, std::size_t size) {
  return fuzz_read_mesh_as(MeshFormat::Stl, data, size);
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_read_stl)
