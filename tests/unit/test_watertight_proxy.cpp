// The watertight proxy: soups, open and multi-part meshes become one closed manifold surface.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "graph/serialize.hpp"
#include "mesh/connected_components.hpp"
#include "mesh/surface_area.hpp"
#include "mesh/watertight_proxy.hpp"
#include "pipeline/build_arg.hpp"
#include "test_mesh_inspection.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

// An axis-aligned box as 12 triangles with its own 8 corners (not shared with anything).
void add_box(Mesh& m, const Eigen::RowVector3d& lo, const Eigen::RowVector3d& hi) {
  const Eigen::Index base = m.V.rows();
  m.V.conservativeResize(base + 8, 3);
  for (int k = 0; k < 8; ++k)
    m.V.row(base + k) << (k & 1 ? hi[0] : lo[0]), (k & 2 ? hi[1] : lo[1]), (k & 4 ? hi[2] : lo[2]);
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  const Eigen::Index f0 = m.F.rows();
  m.F.conservativeResize(f0 + 12, 3);
  for (int f = 0; f < 12; ++f)
    for (int c = 0; c < 3; ++c) m.F(f0 + f, c) = int(base) + faces[f][c];
}

Mesh two_intersecting_boxes() {
  Mesh m;
  m.V.resize(0, 3);
  m.F.resize(0, 3);
  add_box(m, {0, 0, 0}, {2, 1, 1});
  add_box(m, {0.5, -0.5, 0.25}, {1.5, 1.5, 0.75});  // pierces the first box across y
  return m;
}

TEST(WatertightProxy, ASoupOfTwoIntersectingBoxesBecomesOneClosedManifold) {
  const Mesh soup = two_intersecting_boxes();
  std::vector<int> component;
  ASSERT_EQ(vertex_components(soup, component), 2);  // two separate shells that cross
  const Proxy proxy = watertight_proxy(soup);
  const test::Inspection r = test::inspect(proxy.mesh);
  EXPECT_TRUE(r.every_edge_has_two_triangles);
  EXPECT_TRUE(r.every_directed_edge_once);
  EXPECT_TRUE(r.every_fan_is_one_cycle);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.euler(), 2);  // one sphere-like surface: the crossing is filled, not a handle
  EXPECT_GT(r.smallest_area, 0.0);
  // It encloses the union (2 + 1 - 0.5 overlap = 2.5) grown by about one cell (1/48 of 2).
  EXPECT_GT(r.signed_volume, 2.5);
  EXPECT_LT(r.signed_volume, 2.5 * 1.25);
  ASSERT_EQ(proxy.source_face.size(), std::size_t(proxy.mesh.F.rows()));
  for (int f : proxy.source_face) EXPECT_TRUE(f >= 0 && f < soup.F.rows());
}

TEST(WatertightProxy, ASheetBecomesAThinClosedSlabAndAHoleIsClosed) {
  // An open square sheet: its proxy is a closed slab about two offsets thick.
  const Mesh sheet = test::unit_square();
  const test::Inspection slab = test::inspect(watertight_proxy(sheet).mesh);
  EXPECT_TRUE(slab.every_edge_has_two_triangles && slab.every_fan_is_one_cycle);
  EXPECT_EQ(slab.euler(), 2);
  // A sphere with a small hole: the proxy is closed and about the sphere's size.
  Mesh open = test::sphere(30, 40);
  open.F.conservativeResize(open.F.rows() - 3, 3);  // drop three triangles at the south pole
  const Mesh proxy = watertight_proxy(open).mesh;
  const test::Inspection r = test::inspect(proxy);
  EXPECT_TRUE(r.every_edge_has_two_triangles && r.every_fan_is_one_cycle);
  EXPECT_EQ(r.euler(), 2);
  EXPECT_NEAR(surface_area(proxy), 4 * M_PI, 0.2 * 4 * M_PI);
}

TEST(WatertightProxy, PartsFartherApartThanTheOffsetStaySeparate) {
  Mesh m;
  m.V.resize(0, 3);
  m.F.resize(0, 3);
  add_box(m, {0, 0, 0}, {1, 1, 1});
  add_box(m, {3, 0, 0}, {4, 1, 1});
  std::vector<int> component;
  EXPECT_EQ(vertex_components(watertight_proxy(m).mesh, component), 2);
}

TEST(WatertightProxy, BadOptionsAreInputErrors) {
  ProxyOptions bad;
  bad.resolution = 4;
  EXPECT_THROW(watertight_proxy(two_intersecting_boxes(), bad), InputError);
  EXPECT_THROW(watertight_proxy(Mesh{}), InputError);
}

TEST(WatertightProxy, TheBuildUsesItForSoupsAndSaysSo) {
  BuildReport report;
  const ArgGraph g = build_arg(two_intersecting_boxes(), {}, {}, &report);
  EXPECT_TRUE(report.proxy);
  EXPECT_TRUE(g.summary.flags & kFlagProxy);
  EXPECT_EQ(g.summary.components, 2);  // of the input, as given
  EXPECT_EQ(g.nodes.front().level, 0);
  // surface=mesh keeps the old path: mu over the parts joined by one link each.
  BuildOptions mesh_only;
  mesh_only.surface = SurfaceKind::Mesh;
  const ArgGraph h = build_arg(two_intersecting_boxes(), mesh_only, {}, &report);
  EXPECT_FALSE(report.proxy);
  EXPECT_FALSE(h.summary.flags & kFlagProxy);
  // A closed sphere needs no proxy under auto.
  build_arg(test::sphere(), {}, {}, &report);
  EXPECT_FALSE(report.proxy);
}

}  // namespace
}  // namespace arg

namespace arg {
namespace {

TEST(WatertightProxy, BuildsOnItAreTheSameBytesWhateverTheThreadCount) {
  BuildOptions one, three;
  three.threads = 3;
  const Mesh soup = two_intersecting_boxes();
  EXPECT_EQ(serialize_arg(build_arg(soup, one)), serialize_arg(build_arg(soup, three)));
}

TEST(WatertightProxy, ItsDistanceFieldStopsWhenAskedTo) {
  int polls = 0;
  const StopRequested stop = [&] { return ++polls > 1; };
  EXPECT_THROW(watertight_proxy(two_intersecting_boxes(), {}, stop), Interrupted);
}

}  // namespace
}  // namespace arg
