// Where the registered distance field function is kept.
#include "mesh/distance_field.hpp"

#include <atomic>
#include <stdexcept>

namespace arg {

namespace {
std::atomic<DistanceFieldFunction> registered{nullptr};
}  // namespace

void set_distance_field(DistanceFieldFunction function) {
  registered.store(function);
}

DistanceFieldFunction distance_field_function() {
  return registered.load();
}

DistanceField unsigned_distance_field(const Mesh& mesh, const SampleGrid& grid, double band,
                                      const StopRequested& stop) {
  const DistanceFieldFunction f = registered.load();
  if (f == nullptr) throw std::runtime_error("no distance field library is loaded (arg_vdb)");
  return f(mesh, grid, band, stop);
}

}  // namespace arg
