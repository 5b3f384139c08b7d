// Stitching torn surfaces: a cut closes again, closed parts and wide gaps stay apart, and a
// surface with a piece cut off keeps its main piece instead of going to the proxy.
#include <gtest/gtest.h>

#include <vector>

#include "common/errors.hpp"
#include "eval/perturbations.hpp"
#include "mesh/clean_mesh.hpp"
#include "mesh/connected_components.hpp"
#include "mesh/mesh_edges.hpp"
#include "mesh/stitch_pieces.hpp"
#include "pipeline/prepare_surface.hpp"
#include "test_exact_meshes.hpp"
#include "test_shapes.hpp"
#include "test_torn_meshes.hpp"

namespace arg {
namespace {

using test::cleaned;
using test::Pieces;

// The faces whose centre lies above z = cut go up by `gap`, as copies of their own vertices.
Mesh cut_apart(const Mesh& m, double cut, double gap) {
  Mesh out;
  out.V.resize(2 * m.V.rows(), 3);
  out.V << m.V, m.V;
  out.V.bottomRows(m.V.rows()).col(2).array() += gap;
  out.F = m.F;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    double z = 0;
    for (int c = 0; c < 3; ++c) z += m.V(m.F(f, c), 2) / 3;
    if (z > cut) out.F.row(f).array() += int(m.V.rows());
  }
  return out;
}

// Two closed unit spheres, centres `apart` along x.
Mesh two_spheres(double apart) {
  const Mesh a = test::icosphere(2);
  Mesh two;
  two.V.resize(2 * a.V.rows(), 3);
  two.V << a.V, a.V;
  two.V.bottomRows(a.V.rows()).col(0).array() += apart;
  two.F.resize(2 * a.F.rows(), 3);
  two.F << a.F, a.F.array() + int(a.V.rows());
  return two;
}

TEST(StitchPieces, ASphereCutInTwoBecomesTheClosedSphereAgain) {
  const Mesh sphere = test::icosphere(3);
  const Pieces torn = cleaned(cut_apart(sphere, 0.1, 0.004));
  ASSERT_EQ(torn.count, 2);
  std::size_t pairs = 0;
  const Mesh moved =
      stitch_pieces(torn.mesh, mesh_edges(torn.mesh.F), torn.component, 0.02, &pairs);
  EXPECT_GT(pairs, 0u);
  CleanReport report;
  const Pieces joined = cleaned(moved, &report);
  EXPECT_EQ(joined.count, 1);
  EXPECT_EQ(report.boundary_edges, 0u);
  EXPECT_EQ(report.nonmanifold_edges, 0u);
  EXPECT_EQ(joined.mesh.V.rows(), sphere.V.rows());
  EXPECT_EQ(joined.mesh.F.rows(), sphere.F.rows());
}

TEST(StitchPieces, AskedToStopItStops) {
  const Pieces torn = cleaned(cut_apart(test::icosphere(3), 0.1, 0.004));
  const StopRequested stop = [] { return true; };
  EXPECT_THROW(
      stitch_pieces(torn.mesh, mesh_edges(torn.mesh.F), torn.component, 0.02, nullptr, stop),
      Interrupted);
}

TEST(StitchPieces, GapsWiderThanTheToleranceStayOpen) {
  const Pieces torn = cleaned(cut_apart(test::icosphere(3), 0.1, 0.05));
  std::size_t pairs = 1;
  const Mesh moved =
      stitch_pieces(torn.mesh, mesh_edges(torn.mesh.F), torn.component, 0.02, &pairs);
  EXPECT_EQ(pairs, 0u);
  EXPECT_TRUE(moved.V == torn.mesh.V);
}

TEST(StitchPieces, ClosedPartsAndARimOfOnePieceAreLeftAlone) {
  // Two closed spheres nearly touching: no rim, nothing to stitch.
  const Mesh a = test::icosphere(2);
  const Pieces closed = cleaned(two_spheres(2.001));
  ASSERT_EQ(closed.count, 2);
  std::size_t pairs = 1;
  stitch_pieces(closed.mesh, mesh_edges(closed.mesh.F), closed.component, 0.05, &pairs);
  EXPECT_EQ(pairs, 0u);
  // One open piece: its rim's vertices are near each other but in the same piece.
  Mesh open = a;
  open.F.conservativeResize(a.F.rows() - 1, 3);
  const Pieces single = cleaned(open);
  stitch_pieces(single.mesh, mesh_edges(single.mesh.F), single.component, 10.0, &pairs);
  EXPECT_EQ(pairs, 0u);
}

TEST(StitchPieces, ASplitScanIsOneSurfaceForMuNotAProxy) {
  // perturb's split at strength 3: three cuts through the middle, sides 0.2% of the size apart.
  const Mesh torn = perturb(test::capsule(), Perturbation::Split, 3, 1);
  ASSERT_GT(cleaned(torn).count, 2);
  const PreparedSurface prepared = prepare_surface(torn, BuildOptions{});
  EXPECT_GT(prepared.stitched_pairs, 0u);
  EXPECT_EQ(prepared.components, 1u);
  EXPECT_FALSE(prepared.use_proxy);
  EXPECT_GT(prepared.clean.boundary_edges, 0u) << "the input was open: the flag says so";
  // holes=keep asks for the surface as given: in pieces, so the proxy.
  BuildOptions keep;
  keep.holes = HoleKind::Keep;
  const PreparedSurface as_given = prepare_surface(torn, keep);
  EXPECT_EQ(as_given.stitched_pairs, 0u);
  EXPECT_TRUE(as_given.use_proxy);
}

TEST(StitchPieces, AHoleThatCutsATipOffKeepsTheMainPiece) {
  // A capsule (z in [-3.5, 3.5]) loses a ring of faces near one end: the end is a separate
  // piece with about 7% of the area, moved aside so that its rim does not face the stump
  // (facing rims are bridged: test_bridge_pieces.cpp).
  const Mesh cut = test::capsule_cut(2.6, 2.9, {1.5, 0, 0});
  ASSERT_EQ(cleaned(cut).count, 2);
  const PreparedSurface prepared = prepare_surface(cut, BuildOptions{});
  EXPECT_EQ(prepared.bridged_pieces, 0u);
  EXPECT_EQ(prepared.set_aside_pieces, 1u);
  EXPECT_EQ(prepared.components, 1u);
  EXPECT_FALSE(prepared.use_proxy);
  EXPECT_EQ(prepared.filled_loops, 1u);  // the main piece's rim is closed
}

TEST(StitchPieces, AModelOfTwoClosedPartsStillGoesToTheProxy) {
  const PreparedSurface prepared = prepare_surface(two_spheres(3), BuildOptions{});
  EXPECT_EQ(prepared.stitched_pairs, 0u);
  EXPECT_EQ(prepared.set_aside_pieces, 0u);
  EXPECT_EQ(prepared.components, 2u);
  EXPECT_TRUE(prepared.use_proxy);
}

TEST(StitchPieces, FacesAroundAFinAreDropped) {
  // Three triangles on the edge 0-1: a fin; the fourth face is elsewhere and stays.
  const Mesh fin =
      test::mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {1, 1, 0}},
                    {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {1, 5, 2}});
  const Mesh out = without_nonmanifold_faces(fin, mesh_edges(fin.F));
  ASSERT_EQ(out.F.rows(), 1);
  EXPECT_TRUE(out.F.row(0) == fin.F.row(3));
}

}  // namespace
}  // namespace arg
