// Bridging pieces that a hole cut apart: a limb cut off by a ring-shaped hole joins its body
// again by a tube, closed and consistently turned; pieces that do not face each other, pieces
// too far apart, loops of one piece and closed parts are left alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/errors.hpp"
#include "mesh/bridge_pieces.hpp"
#include "mesh/mesh_edges.hpp"
#include "pipeline/prepare_surface.hpp"
#include "test_exact_meshes.hpp"
#include "test_torn_meshes.hpp"

namespace arg {
namespace {

using test::capsule_cut;
using test::cleaned;
using test::Pieces;
using test::signed_volume;

double longest_edge(const Mesh& m) {
  const MeshEdges edges = mesh_edges(m.F);
  double longest = 0;
  for (int e = 0; e < edges.count(); ++e)
    longest = std::max(longest, (m.V.row(edges.v0[e]) - m.V.row(edges.v1[e])).norm());
  return longest;
}

// The pieces bridged (gaps up to 1), then cleaned: the surface prepare_surface would go on with.
Pieces bridged(const Pieces& torn, std::size_t& bridges, CleanReport& report) {
  return cleaned(bridge_pieces(torn.mesh, mesh_edges(torn.mesh.F), torn.component, 1.0, &bridges),
                 &report);
}

TEST(BridgePieces, ALimbCutOffByAHoleIsJoinedByAClosedTube) {
  const Pieces torn = cleaned(capsule_cut(1.0, 1.6));
  ASSERT_EQ(torn.count, 2);
  std::size_t bridges = 0;
  CleanReport report;
  const Pieces joined = bridged(torn, bridges, report);
  EXPECT_EQ(bridges, 1u);
  EXPECT_EQ(joined.count, 1);
  EXPECT_EQ(report.boundary_edges, 0u) << "the tube takes up both rims";
  EXPECT_EQ(report.nonmanifold_edges, 0u);
  EXPECT_EQ(report.flipped_faces, 0u) << "the tube turns as the pieces do";
  // The tube stands where the ring was: the volume is the capsule's.
  const double whole = std::abs(signed_volume(test::capsule()));
  EXPECT_NEAR(std::abs(signed_volume(joined.mesh)), whole, 0.01 * whole);
  // Rings every rim edge or so: no sliver spanning the whole gap.
  EXPECT_LT(longest_edge(joined.mesh), 0.3);
}

TEST(BridgePieces, APieceTurnedInsideOutIsStillJoined) {
  Pieces torn = cleaned(capsule_cut(1.0, 1.6));
  for (Eigen::Index f = 0; f < torn.mesh.F.rows(); ++f)
    if (torn.component[std::size_t(torn.mesh.F(f, 0))] == 1)
      std::swap(torn.mesh.F(f, 1), torn.mesh.F(f, 2));
  std::size_t bridges = 0;
  CleanReport report;
  const Pieces joined = bridged(torn, bridges, report);
  EXPECT_EQ(bridges, 1u);
  EXPECT_EQ(joined.count, 1);
  EXPECT_EQ(report.boundary_edges, 0u);
  EXPECT_EQ(report.nonmanifold_edges, 0u);
  // Not twisted: walked the other way, the turned piece's loop still meets the other in order.
  const double whole = std::abs(signed_volume(test::capsule()));
  EXPECT_NEAR(std::abs(signed_volume(joined.mesh)), whole, 0.01 * whole);
  EXPECT_LT(longest_edge(joined.mesh), 0.3);
}

TEST(BridgePieces, PiecesThatDoNotFaceEachOtherOrLieFarApartStayApart) {
  std::size_t bridges = 1;
  // The limb moved sideways: its rim opens past the stump, not towards it.
  const Pieces aside = cleaned(capsule_cut(1.0, 1.6, {3, 0, 0}));
  ASSERT_EQ(aside.count, 2);
  bridge_pieces(aside.mesh, mesh_edges(aside.mesh.F), aside.component, 10.0, &bridges);
  EXPECT_EQ(bridges, 0u);
  // Facing, but farther apart than allowed.
  const Pieces far = cleaned(capsule_cut(1.0, 1.6));
  const Mesh same = bridge_pieces(far.mesh, mesh_edges(far.mesh.F), far.component, 0.5, &bridges);
  EXPECT_EQ(bridges, 0u);
  EXPECT_EQ(same.F.rows(), far.mesh.F.rows());
  // Loops of one piece are never bridged to each other: the torn capsule, told it is one piece.
  const Pieces torn = cleaned(capsule_cut(1.0, 1.6));
  const std::vector<int> one_piece(torn.component.size(), 0);
  bridge_pieces(torn.mesh, mesh_edges(torn.mesh.F), one_piece, 10.0, &bridges);
  EXPECT_EQ(bridges, 0u);
}

TEST(BridgePieces, AFlatPieceIsNotBridgedThoughItFacesARim) {
  // A lone triangle across the gap, nearer to both rims than they are to each other: which way
  // it is turned is unknown, so the stump and the limb are joined past it.
  const Mesh cut = capsule_cut(1.0, 1.6);
  Mesh with_triangle = cut;
  const Eigen::Index first = cut.V.rows();
  with_triangle.V.conservativeResize(first + 3, 3);
  for (int k = 0; k < 3; ++k)
    with_triangle.V.row(first + k) << 0.4 * std::cos(2 * M_PI * k / 3),
        0.4 * std::sin(2 * M_PI * k / 3), 1.3;
  with_triangle.F.conservativeResize(cut.F.rows() + 1, 3);
  with_triangle.F.row(cut.F.rows()) << int(first), int(first) + 1, int(first) + 2;
  const Pieces torn = cleaned(with_triangle);
  ASSERT_EQ(torn.count, 3);
  std::size_t bridges = 0;
  CleanReport report;
  const Pieces joined = bridged(torn, bridges, report);
  EXPECT_EQ(bridges, 1u);
  ASSERT_EQ(joined.count, 2);
  const std::ptrdiff_t in_first = std::count(joined.component.begin(), joined.component.end(), 0);
  EXPECT_EQ(std::min<std::ptrdiff_t>(in_first, joined.mesh.V.rows() - in_first), 3)
      << "the triangle stays a piece of its own";
  // The capsule's piece, without the open triangle (whose faces enclose nothing), is whole.
  Mesh capsule_piece = joined.mesh;
  Eigen::Index kept = 0;
  const int big = in_first > 3 ? 0 : 1;
  for (Eigen::Index f = 0; f < joined.mesh.F.rows(); ++f)
    if (joined.component[std::size_t(joined.mesh.F(f, 0))] == big)
      capsule_piece.F.row(kept++) = joined.mesh.F.row(f);
  capsule_piece.F.conservativeResize(kept, 3);
  const double whole = std::abs(signed_volume(test::capsule()));
  EXPECT_NEAR(std::abs(signed_volume(capsule_piece)), whole, 0.01 * whole);
}

TEST(BridgePieces, ClosedPartsHaveNoRimToBridge) {
  const Mesh a = test::icosphere(2);
  Mesh two;
  two.V.resize(2 * a.V.rows(), 3);
  two.V << a.V, a.V;
  two.V.bottomRows(a.V.rows()).col(0).array() += 2.5;
  two.F.resize(2 * a.F.rows(), 3);
  two.F << a.F, a.F.array() + int(a.V.rows());
  const Pieces parts = cleaned(two);
  ASSERT_EQ(parts.count, 2);
  std::size_t bridges = 1;
  bridge_pieces(parts.mesh, mesh_edges(parts.mesh.F), parts.component, 10.0, &bridges);
  EXPECT_EQ(bridges, 0u);
}

TEST(BridgePieces, AskedToStopItStops) {
  const Pieces torn = cleaned(capsule_cut(1.0, 1.6));
  const StopRequested stop = [] { return true; };
  EXPECT_THROW(
      bridge_pieces(torn.mesh, mesh_edges(torn.mesh.F), torn.component, 1.0, nullptr, stop),
      Interrupted);
}

TEST(BridgePieces, ALimbCutOffIsMeasuredAsOneSurfaceNotAProxy) {
  // The limb above the cut holds far more than a tenth of the area: before bridging, this
  // surface went to the proxy.
  const PreparedSurface prepared = prepare_surface(capsule_cut(-0.3, 0.3), BuildOptions{});
  EXPECT_EQ(prepared.bridged_pieces, 1u);
  EXPECT_EQ(prepared.components, 1u);
  EXPECT_EQ(prepared.set_aside_pieces, 0u);
  EXPECT_FALSE(prepared.use_proxy);
  EXPECT_EQ(prepared.filled_loops, 0u) << "the tube took both rims: nothing left to fill";
}

}  // namespace
}  // namespace arg
