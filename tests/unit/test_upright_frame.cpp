// The canonical view: generated tables and figures stand upright, whichever way they are turned.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "gen/generate_models.hpp"
#include "render/upright_frame.hpp"
#include "test_shapes.hpp"

namespace {

using arg::upright_frame;
using arg::UprightFrame;

// The generator builds its models with +z up; the figures face +x.
const Eigen::Vector3d kUp = Eigen::Vector3d::UnitZ();

arg::Mesh generated(const std::string& label, int variant) {
  return arg::generate_model(label, variant, 32, false).mesh;
}

TEST(UprightFrame, GeneratedTablesStandOnTheirLegs) {
  for (int variant = 0; variant < 4; ++variant) {
    const UprightFrame frame = upright_frame(generated("table", variant));
    EXPECT_GT(frame.up.dot(kUp), 0.99) << "table " << variant << " up " << frame.up.transpose();
    // Seen across its long side: front along the table's width (y), not its length (x).
    EXPECT_GT(std::abs(frame.front.y()), 0.9) << "table " << variant;
  }
}

TEST(UprightFrame, GeneratedFiguresStandOnTheirFeet) {
  // Variants 0 to 2: arms down, out, raised. The fourth, one arm raised, comes out on its head
  // (docs/BENCHMARKS.md, "Upright pictures").
  for (int variant = 0; variant < 3; ++variant) {
    const UprightFrame frame = upright_frame(generated("human", variant));
    EXPECT_GT(frame.up.dot(kUp), 0.99) << "figure " << variant << " up " << frame.up.transpose();
    // Seen from the front or the back (x), so that the picture shows the shoulders across.
    EXPECT_GT(std::abs(frame.front.x()), 0.9) << "figure " << variant;
  }
}

TEST(UprightFrame, TurnedUpsideDownComesOutTheSame) {
  // Upside down (half a turn about x), turned about z, moved and scaled: the same sides are up
  // and front, in the turned copy's coordinates.
  const Eigen::Matrix3d flip = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 0.5, 1).normalized()) *
                                Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()))
                                   .toRotationMatrix();
  for (const char* label : {"table", "human"}) {
    const arg::Mesh mesh = generated(label, 1);
    const UprightFrame frame = upright_frame(mesh);
    const UprightFrame turned =
        upright_frame(arg::test::transformed(mesh, flip, Eigen::Vector3d(3, -2, 5), 2.5));
    EXPECT_GT(turned.up.dot(flip * frame.up), 0.999) << label;
    EXPECT_GT(turned.front.dot(flip * frame.front), 0.999) << label;
    EXPECT_GT(turned.up.dot(flip * kUp), 0.99) << label << ": the copy's own up is up";
  }
}

TEST(UprightFrame, SidesAreMeasuredFromTheCentroid) {
  // A capsule along z, 4 long and 1 across: the floor below each end is 2 below the centroid,
  // below its side 0.5 (heights in RMS radii, so compared as a ratio); the centroid's foot is
  // inside the support polygon of every side.
  const UprightFrame frame = upright_frame(arg::test::capsule(1.5, 0.5));
  double end_height = 0, side_height = 0, broadest = 0, best = 0;
  for (const arg::RestingSide& side : frame.sides) {
    EXPECT_NEAR(side.down.norm(), 1, 1e-12);
    EXPECT_GT(side.margin, 0);
    EXPECT_GT(side.support, 0);
    (std::abs(side.down.z()) > 0.99 ? end_height : side_height) = side.height;
    broadest = std::max(broadest, side.support);
    best = std::max(best, side.score);
  }
  EXPECT_NEAR(side_height / end_height, 0.25, 0.01);
  // The rule: only a broad base counts, and the side chosen scores best (its two ends tie).
  double chosen = -1;
  for (const arg::RestingSide& side : frame.sides) {
    if (side.support < 0.4 * broadest) {
      EXPECT_EQ(side.score, 0);
    }
    if (frame.up.isApprox(-side.down, 1e-12)) chosen = side.score;
  }
  EXPECT_EQ(chosen, best);
}

TEST(UprightFrame, ViewLooksAtTheFrontWithUpUpright) {
  const UprightFrame frame = upright_frame(generated("human", 0));
  const Eigen::Matrix3d view = arg::upright_view(frame);
  EXPECT_TRUE((view * view.transpose()).isIdentity(1e-9));
  EXPECT_NEAR(view.determinant(), 1, 1e-9);
  EXPECT_TRUE((view * frame.up).isApprox(Eigen::Vector3d::UnitY(), 1e-9));
  EXPECT_TRUE((view * frame.front).isApprox(Eigen::Vector3d::UnitZ(), 1e-9));
}

TEST(UprightFrame, SurfaceWithoutAreaKeepsTheDefaults) {
  arg::Mesh flat;
  flat.V = arg::Vertices::Zero(3, 3);
  flat.F = arg::Triangles(1, 3);
  flat.F << 0, 1, 2;
  const UprightFrame frame = upright_frame(flat);
  EXPECT_EQ(frame.up, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(frame.front, Eigen::Vector3d::UnitY());
}

}  // namespace
