// Degenerate and hostile meshes get a typed error or a defined result, quickly.
#include <gtest/gtest.h>

#include <chrono>

#include "common/errors.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "mesh/clean_mesh.hpp"
#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

Mesh mesh_of(std::vector<Eigen::RowVector3d> v, std::vector<Eigen::RowVector3i> f) {
  Mesh m;
  m.V.resize(Eigen::Index(v.size()), 3);
  for (std::size_t i = 0; i < v.size(); ++i) m.V.row(Eigen::Index(i)) = v[i];
  m.F.resize(Eigen::Index(f.size()), 3);
  for (std::size_t i = 0; i < f.size(); ++i) m.F.row(Eigen::Index(i)) = f[i];
  return m;
}

std::string message_of(const Mesh& m) {
  try {
    build_arg(m);
  } catch (const InputError& e) {
    return e.what();
  }
  return "built";
}

}  // namespace

TEST(Limits, ZeroAreaAndCollinearMeshesAreInputErrors) {
  EXPECT_NE(
      message_of(mesh_of({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}, {{0, 1, 2}, {1, 2, 3}}))
          .find("no face with positive area"),
      std::string::npos);
  EXPECT_NE(
      message_of(mesh_of({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, {{0, 1, 2}})).find("positive area"),
      std::string::npos);
  EXPECT_NE(message_of(Mesh{}).find("no faces"), std::string::npos);
}

TEST(Limits, ASingleTriangleBuildsAGraphOfOneComponent) {
  ArgGraph g = build_arg(mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  EXPECT_EQ(g.level_begin[1] - g.level_begin[0], 1u);
  EXPECT_EQ(g.summary.triangles, 1u);
  EXPECT_EQ(g.summary.flags & 1, 1);  // open
  EXPECT_EQ(deserialize_arg(serialize_arg(g)).nodes.size(), g.nodes.size());
  EXPECT_EQ(arg_similarity(g, g), 0.0);
}

TEST(Limits, DuplicatedFacesAreDroppedAndGiveTheSameGraph) {
  Mesh m = test::torus(2, 0.6, 40, 16);
  Mesh doubled = m;
  doubled.F.conservativeResize(m.F.rows() * 2, 3);
  doubled.F.bottomRows(m.F.rows()) = m.F;
  CleanReport report;
  clean_mesh(doubled, &report);
  EXPECT_EQ(report.dropped_duplicate, std::size_t(m.F.rows()));
  EXPECT_EQ(serialize_arg(build_arg(doubled)), serialize_arg(build_arg(m)));
}

TEST(Limits, InconsistentOrientationIsRepairedAndGivesTheSameGraph) {
  Mesh m = test::torus(2, 0.6, 40, 16);
  Mesh scrambled = m;
  for (Eigen::Index f = 0; f < m.F.rows(); f += 3) std::swap(scrambled.F(f, 1), scrambled.F(f, 2));
  CleanReport report;
  clean_mesh(scrambled, &report);
  EXPECT_GT(report.flipped_faces, 0u);
  EXPECT_EQ(serialize_arg(build_arg(scrambled)), serialize_arg(build_arg(m)));
}

TEST(Limits, NanVerticesAndBadIndicesAreInputErrors) {
  EXPECT_NE(message_of(mesh_of({{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}}, {{0, 1, 2}})).find("NaN"),
            std::string::npos);
  EXPECT_NE(message_of(mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 7}})).find("vertex 7"),
            std::string::npos);
}

TEST(Limits, CapsGiveLimitErrorsBeforeAnyWork) {
  Limits small;
  small.max_input_bytes = 100;
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_THROW(build_arg_bytes(std::string(1000, ' '), {}, {}, small), LimitError);
  small = Limits{};
  small.max_vertices = 10;
  EXPECT_THROW(build_arg_bytes("OFF\n100 1 0\n" + std::string(100, '\n'), {}, {}, small), Error);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
}
