// Narrow-band unsigned distances and nearest triangles from OpenVDB's mesh-to-volume conversion.
#include "vdb/vdb_distance_field.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <tbb/task_arena.h>

#include <mutex>

#include "common/errors.hpp"

namespace arg {

namespace {

// OpenVDB asks this between its passes; the core's callback says whether to stop. Derived
// from NullInterrupter and passed as one, so that the call below is the meshToVolume that
// libopenvdb already holds compiled (its explicit instantiations take a NullInterrupter&):
// instantiating the template here took 6 minutes to compile under the sanitizers.
struct StopInterrupter : openvdb::util::NullInterrupter {
  explicit StopInterrupter(const StopRequested* s) : stop(s) {}
  const StopRequested* stop = nullptr;
  bool stopped = false;
  bool wasInterrupted(int = -1) override {
    if (!stopped && *stop && (*stop)()) stopped = true;
    return stopped;
  }
};

}  // namespace

DistanceField vdb_distance_field(const Mesh& mesh, const SampleGrid& grid, double band,
                                 const StopRequested& stop) {
  static std::once_flag initialised;
  std::call_once(initialised, [] { openvdb::initialize(); });
  if (!(grid.step > 0) || !(band > 0) || grid.nx < 1 || grid.ny < 1 || grid.nz < 1)
    throw InputError("distance field: empty grid or band");

  // The mesh in the grid's index space (grid point (i, j, k) at integer coordinates).
  std::vector<openvdb::Vec3s> points(std::size_t(mesh.V.rows()));
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    points[std::size_t(v)] = openvdb::Vec3s(float((mesh.V(v, 0) - grid.origin[0]) / grid.step),
                                            float((mesh.V(v, 1) - grid.origin[1]) / grid.step),
                                            float((mesh.V(v, 2) - grid.origin[2]) / grid.step));
  std::vector<openvdb::Vec3I> triangles(std::size_t(mesh.F.rows()));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    triangles[std::size_t(f)] =
        openvdb::Vec3I(openvdb::Index32(mesh.F(f, 0)), openvdb::Index32(mesh.F(f, 1)),
                       openvdb::Index32(mesh.F(f, 2)));
  openvdb::math::Transform::Ptr transform =
      openvdb::math::Transform::createLinearTransform(grid.step);
  const openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(
      points, triangles);
  const float band_voxels = float(band / grid.step);

  DistanceField out;
  out.grid = grid;
  out.far = float(band);
  const std::size_t count = std::size_t(grid.nx) * std::size_t(grid.ny) * std::size_t(grid.nz);
  out.distance.assign(count, out.far);
  out.nearest.assign(count, -1);

  StopInterrupter stop_interrupter(&stop);
  openvdb::util::NullInterrupter& interrupter = stop_interrupter;
  openvdb::Int32Grid index_grid(-1);
  openvdb::FloatGrid::Ptr field;
  // One slot: OpenVDB's passes run on this thread only, so no thread of the host process is
  // started and the nearest triangle of a tie is the same on every run.
  tbb::task_arena arena(1);
  arena.execute([&] {
    field = openvdb::tools::meshToVolume<openvdb::FloatGrid>(
        interrupter, adapter, *transform, band_voxels, band_voxels,
        openvdb::tools::UNSIGNED_DISTANCE_FIELD, &index_grid);
  });
  if (stop_interrupter.stopped || (stop && stop())) throw Interrupted();

  const auto index_of = [&](const openvdb::Coord& c) -> long long {
    if (c.x() < 0 || c.y() < 0 || c.z() < 0 || c.x() >= grid.nx || c.y() >= grid.ny ||
        c.z() >= grid.nz)
      return -1;
    return (static_cast<long long>(c.z()) * grid.ny + c.y()) * grid.nx + c.x();
  };
  for (auto it = field->cbeginValueOn(); it; ++it) {
    const long long k = index_of(it.getCoord());
    if (k >= 0) out.distance[std::size_t(k)] = std::min(out.far, *it);
  }
  for (auto it = index_grid.cbeginValueOn(); it; ++it) {
    const long long k = index_of(it.getCoord());
    if (k >= 0 && *it >= 0 && *it < mesh.F.rows()) out.nearest[std::size_t(k)] = *it;
  }
  return out;
}

}  // namespace arg

void* arg_vdb_distance_field() {
  return reinterpret_cast<void*>(&arg::vdb_distance_field);
}
