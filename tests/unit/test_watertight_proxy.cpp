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

Eigen::RowVector3d face_centre(const Mesh& m, Eigen::Index f) {
  return (m.V.row(m.F(f, 0)) + m.V.row(m.F(f, 1)) + m.V.row(m.F(f, 2))) / 3.0;
}

// The unit sphere without the faces whose centre lies above z = `above`.
Mesh sphere_cut_above(double above) {
  const Mesh whole = test::sphere(40, 60);
  Mesh cut = whole;
  Eigen::Index kept = 0;
  for (Eigen::Index f = 0; f < whole.F.rows(); ++f)
    if (face_centre(whole, f)[2] <= above) cut.F.row(kept++) = whole.F.row(f);
  cut.F.conservativeResize(kept, 3);
  return cut;
}

// The first flood alone, as builders before 1.5 made the proxy.
ProxyOptions flood_only() {
  ProxyOptions o;
  o.min_open = 0;
  return o;
}

TEST(WatertightProxy, AShapeWithAHoleWiderThanTheOffsetKeepsItsVolume) {
  // A cap of radius 0.6 gone: the hole is about 29 cells wide, and the flood gets in.
  const Mesh open = sphere_cut_above(0.8);
  const double ball = 4.0 / 3.0 * M_PI;
  const test::Inspection shell = test::inspect(watertight_proxy(open, flood_only()).mesh);
  EXPECT_LT(shell.signed_volume, 0.5 * ball);  // the flood alone: a thin shell of the surface
  const test::Inspection r = test::inspect(watertight_proxy(open).mesh);
  EXPECT_TRUE(r.every_edge_has_two_triangles && r.every_fan_is_one_cycle);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.euler(), 2);
  EXPECT_GT(r.signed_volume, 0.85 * ball);  // what saw out only through the hole is filled
  EXPECT_LT(r.signed_volume, 1.25 * ball);
}

TEST(WatertightProxy, WhatClosesAHoleTakesItsColourFromNearbyFaces) {
  // The triangles that close what saw out only through the hole lie away from the input: each
  // still takes an input triangle about as near as the nearest (within 6 cells of 1/24).
  const Mesh open = sphere_cut_above(0.8);
  const Proxy proxy = watertight_proxy(open);
  ASSERT_EQ(proxy.source_face.size(), std::size_t(proxy.mesh.F.rows()));
  std::vector<Eigen::RowVector3d> centres;
  for (Eigen::Index g = 0; g < open.F.rows(); ++g) centres.push_back(face_centre(open, g));
  double worst = 0;
  for (Eigen::Index f = 0; f < proxy.mesh.F.rows(); f += 5) {  // every fifth: a second or so
    const Eigen::RowVector3d c = face_centre(proxy.mesh, f);
    double nearest = HUGE_VAL;
    for (const Eigen::RowVector3d& p : centres) nearest = std::min(nearest, (p - c).squaredNorm());
    nearest = std::sqrt(nearest);
    const int s = proxy.source_face[std::size_t(f)];
    ASSERT_TRUE(s >= 0 && s < open.F.rows());
    worst = std::max(worst, (centres[std::size_t(s)] - c).norm() - nearest);
  }
  EXPECT_LT(worst, 0.25);
}

TEST(WatertightProxy, ADishAndASheetSeeOutAndStayThin) {
  // A spherical cap 0.4 deep and 1.6 wide: every point of its inside sees much of the sky, so
  // it stays the thin slab the flood alone gives (filled, it would hold about 0.44 more).
  const Mesh dish = sphere_cut_above(-0.6);
  const double thin = test::inspect(watertight_proxy(dish, flood_only()).mesh).signed_volume;
  const test::Inspection r = test::inspect(watertight_proxy(dish).mesh);
  EXPECT_TRUE(r.every_edge_has_two_triangles && r.every_fan_is_one_cycle);
  EXPECT_LT(r.signed_volume, thin + 0.1);
  const test::Inspection slab = test::inspect(watertight_proxy(test::unit_square()).mesh);
  EXPECT_LT(slab.signed_volume, 0.1);  // about 1 x 1 x two offsets (2 / 48)
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
  ProxyOptions too_many;
  too_many.min_open = 27;
  EXPECT_THROW(watertight_proxy(two_intersecting_boxes(), too_many), InputError);
  ProxyOptions negative;
  negative.min_open = -1;
  EXPECT_THROW(watertight_proxy(two_intersecting_boxes(), negative), InputError);
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
