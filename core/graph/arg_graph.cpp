// Version stamp of the builder that made an ARG.
#include "graph/arg_graph.hpp"

namespace arg {

std::uint32_t current_builder_version() {
  // Bump when a change to the method changes the bytes built from the same mesh.
  return 1 * 10000 + 1 * 100 + 0;
}

}  // namespace arg
