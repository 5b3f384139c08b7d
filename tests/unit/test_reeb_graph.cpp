// The multiresolution Reeb graph, checked the way the paper describes it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <map>
#include <numeric>

#include "common/errors.hpp"
#include "graph/serialize.hpp"
#include "mesh/clean_mesh.hpp"
#include "mesh/mesh_edges.hpp"
#include "mesh/normalize_pose.hpp"
#include "mu/mu_function.hpp"
#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

int nodes_at(const ArgGraph& g, int level) {
  return int(g.level_begin[std::size_t(level) + 1] - g.level_begin[std::size_t(level)]);
}

}  // namespace

TEST(ReebGraph, SphereHasOneNodePerIntervalAndNoLoops) {
  // Height has exactly two critical points on a sphere, so every interval is one disc or band.
  BuildOptions height;
  height.mu = MuKind::Height;
  ArgGraph g = build_arg(test::sphere(40, 60, 1.5, 1, 1), height);
  EXPECT_EQ(g.summary.genus, 0);
  for (int r = 0; r <= g.levels(); ++r) EXPECT_EQ(nodes_at(g, r), 1 << r) << "level " << r;
  // The geodesic integral is nearly constant on a round sphere, so its graph has many
  // nodes, but still one component and no loop.
  ArgGraph geodesic = build_arg(test::sphere());
  EXPECT_EQ(geodesic.summary.genus, 0);
  EXPECT_EQ(nodes_at(geodesic, 0), 1);
}

TEST(ReebGraph, TorusHasOneLoop) {
  ArgGraph g = build_arg(test::torus());
  EXPECT_EQ(g.summary.genus, 1);
}

// Stored areas and lengths are rounded to 1/65,535 (format 3): half a step a node.
double stored_rounding(std::size_t nodes) {
  return 0.5 / 65535.0 * double(nodes) + 1e-6;
}

TEST(ReebGraph, AreasOfEveryLevelSumToOneOverLevelsPlusOne) {
  ArgGraph g = build_arg(test::torus());
  for (int r = 0; r <= g.levels(); ++r) {
    double a = 0, l = 0;
    for (auto i = g.level_begin[r]; i < g.level_begin[r + 1]; ++i)
      a += g.nodes[i].a, l += g.nodes[i].l;
    const double tolerance = stored_rounding(g.level_begin[r + 1] - g.level_begin[r]);
    EXPECT_NEAR(a, 1.0 / (g.levels() + 1), tolerance) << "level " << r;
    EXPECT_NEAR(l, 1.0 / (g.levels() + 1), tolerance) << "level " << r;
  }
}

TEST(ReebGraph, ParentAreaIsTheSumOfItsChildren) {
  ArgGraph g = build_arg(test::torus());
  for (const ArgNode& n : g.nodes) {
    if (n.child_count == 0) continue;
    double sum = 0;
    for (std::uint32_t k = 0; k < n.child_count; ++k)
      sum += g.nodes[g.children[n.child_begin + k]].a;
    EXPECT_NEAR(n.a, sum, stored_rounding(n.child_count + 1));
  }
}

TEST(ReebGraph, RelativeVolumesSumToAboutOneOverLevelsPlusOneOnClosedMeshes) {
  // Genus 0 only: a band running around a handle, closed by its caps, can enclose a negative
  // signed volume, which is clamped to 0, so a torus sums to more.
  for (const Mesh& m : {test::sphere(), test::sphere(40, 60, 2, 1, 0.7), test::capsule()}) {
    ArgGraph g = build_arg(m);
    for (int r = 0; r <= g.levels(); ++r) {
      double v = 0;
      for (auto i = g.level_begin[r]; i < g.level_begin[r + 1]; ++i) v += g.nodes[i].v;
      EXPECT_NEAR(v, 1.0 / (g.levels() + 1), 0.03) << "level " << r;
    }
  }
}

TEST(Mu, CylinderMuIsMonotoneAlongItsAxisFromTheMiddle) {
  Mesh m = clean_mesh(test::capsule());
  m = apply_pose(m, surface_pose(m));
  MeshEdges e = mesh_edges(m.F);
  std::vector<double> mu = normalised_mu(m, e, BuildOptions{});
  // mu grows with the distance from the middle of the capsule (x is its axis after PCA).
  std::vector<std::pair<double, double>> by_height;
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) by_height.emplace_back(std::fabs(m.V(v, 0)), mu[v]);
  std::sort(by_height.begin(), by_height.end());
  int inversions = 0;
  for (std::size_t k = 1; k < by_height.size(); ++k)
    if (by_height[k].second + 0.02 < by_height[k - 1].second) ++inversions;
  EXPECT_EQ(inversions, 0);
  EXPECT_LT(by_height.front().second, 0.05);
  EXPECT_GT(by_height.back().second, 0.95);
}

TEST(Mu, InvariantToRotationTranslationScaleAndRenumbering) {
  Mesh base = test::torus(2, 0.7, 60, 24);
  Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Mesh moved = test::transformed(base, R, Eigen::Vector3d(5, -3, 2), 3.5);
  // Renumber vertices by reversing them.
  Mesh renumbered = moved;
  const Eigen::Index n = moved.V.rows();
  for (Eigen::Index i = 0; i < n; ++i) renumbered.V.row(n - 1 - i) = moved.V.row(i);
  for (Eigen::Index f = 0; f < moved.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) renumbered.F(f, c) = int(n - 1 - moved.F(f, c));
  // mu keyed by the vertex position in the input (cleaning may renumber vertices).
  auto mu_of = [](const Mesh& in) {
    Mesh m = clean_mesh(in);
    Mesh posed = apply_pose(m, surface_pose(m));
    std::vector<double> mu = normalised_mu(posed, mesh_edges(posed.F), BuildOptions{});
    std::map<std::array<double, 3>, double> by_position;
    for (Eigen::Index v = 0; v < m.V.rows(); ++v)
      by_position[{m.V(v, 0), m.V(v, 1), m.V(v, 2)}] = mu[v];
    return by_position;
  };
  auto a = mu_of(base), b = mu_of(moved), c = mu_of(renumbered);
  ASSERT_EQ(a.size(), b.size());
  double worst_b = 0, worst_c = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    double at_base = a.at({base.V(i, 0), base.V(i, 1), base.V(i, 2)});
    std::array<double, 3> p{moved.V(i, 0), moved.V(i, 1), moved.V(i, 2)};
    worst_b = std::max(worst_b, std::fabs(at_base - b.at(p)));
    worst_c = std::max(worst_c, std::fabs(at_base - c.at(p)));
  }
  EXPECT_LT(worst_b, 0.05);
  EXPECT_LT(worst_c, 0.05);
}

TEST(Serialisation, RoundTripIsBitExact) {
  ArgGraph g = build_arg(test::torus());
  std::string bytes = serialize_arg(g);
  ArgGraph back = deserialize_arg(bytes);
  EXPECT_EQ(serialize_arg(back), bytes);
  EXPECT_EQ(arg_from_text(arg_to_text(bytes)), bytes);
}

TEST(Serialisation, EveryCorruptedByteIsRejectedOrHarmless) {
  std::string bytes = serialize_arg(build_arg(test::sphere(12, 16)));
  // Flipping any byte breaks the digest or a structural check: never accepted silently.
  for (std::size_t i = 0; i < bytes.size(); i += 7) {
    std::string bad = bytes;
    bad[i] = char(bad[i] ^ 0x5a);
    EXPECT_THROW(deserialize_arg(bad), InputError) << "byte " << i;
  }
  for (std::size_t cut : {std::size_t(0), std::size_t(10), bytes.size() / 2, bytes.size() - 1})
    EXPECT_THROW(deserialize_arg(bytes.substr(0, cut)), InputError);
}

TEST(Build, SameBytesWhateverTheThreadCount) {
  Mesh m = test::torus(2, 0.6, 90, 36);
  BuildOptions one, four;
  four.threads = 4;
  EXPECT_EQ(serialize_arg(build_arg(m, one)), serialize_arg(build_arg(m, four)));
}

TEST(Build, StopsWhenAskedTo) {
  int polls = 0;
  StopRequested stop = [&] { return ++polls > 3; };
  EXPECT_THROW(build_arg(test::torus(2, 0.6, 200, 80), BuildOptions{}, stop), Interrupted);
}
