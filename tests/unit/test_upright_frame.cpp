// The canonical view: generated tables and figures stand upright, whichever way they are turned.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gen/generate_models.hpp"
#include "mesh/normalize_pose.hpp"
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

// A quarter turn about x that takes the generator's +z up to +y, as OBJ files keep it.
const Eigen::Matrix3d kZToY =
    Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();

arg::UprightHint prefer_file_axes() {
  arg::UprightHint hint;
  hint.prefer_file_axes = true;
  return hint;
}

TEST(UprightFrame, FileYUpWinsWhereTheShapeRuleFails) {
  // Four-legged animals drawn +y up: the resting-base rule lays them on their backs (its highest
  // centroid), but each stands on the file's -y floor, so the file's +y is up.
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  for (int variant = 0; variant < 3; ++variant) {
    const arg::Mesh mesh =
        arg::test::transformed(generated("fourleg", variant), kZToY, Eigen::Vector3d::Zero(), 1);
    EXPECT_LT(upright_frame(mesh).up.dot(y), 0.9) << "fourleg " << variant << ": the rule alone";
    const UprightFrame frame = upright_frame(mesh, prefer_file_axes());
    EXPECT_GT(frame.up.dot(y), 0.999) << "fourleg " << variant << " up " << frame.up.transpose();
    EXPECT_NEAR(frame.front.dot(frame.up), 0, 1e-9);
    ASSERT_EQ(frame.file_sides.size(), 2u);
    EXPECT_GT(frame.file_sides[0].score, 0) << "it stands on the file's -y floor";
  }
}

TEST(UprightFrame, FigureDrawnZUpDoesNotLieOnItsBack) {
  // A +z-up standing figure also rests steadily on its back (the file's -y floor); the
  // file's +z holds its centroid far higher, so +z stays up.
  for (int variant = 0; variant < 3; ++variant) {
    const UprightFrame frame = upright_frame(generated("human", variant), prefer_file_axes());
    EXPECT_GT(frame.up.dot(kUp), 0.999) << "figure " << variant << " up " << frame.up.transpose();
  }
}

TEST(UprightFrame, KnownUpIsTakenAsItIs) {
  // A table drawn +z up, said to be -x up (wrong, but the catalogue is believed): up is -x,
  // and the front is across it.
  arg::UprightHint hint;
  hint.up = arg::parse_up_axis("-x");
  const UprightFrame frame = upright_frame(generated("table", 0), hint);
  EXPECT_TRUE(frame.up.isApprox(-Eigen::Vector3d::UnitX(), 1e-12)) << frame.up.transpose();
  EXPECT_NEAR(frame.front.norm(), 1, 1e-9);
  EXPECT_NEAR(frame.front.dot(frame.up), 0, 1e-9);
  EXPECT_TRUE(frame.file_sides.empty());
}

TEST(UprightFrame, FileAxesFollowThePose) {
  // The posed surface (as pictures draw it) with the pose's rotation as the file's axes gives
  // the same up as the surface read from the file, in the posed coordinates.
  const arg::Mesh mesh =
      arg::test::transformed(generated("fourleg", 1), kZToY, Eigen::Vector3d::Zero(), 1);
  const arg::Pose pose = arg::surface_pose(mesh);
  arg::UprightHint hint = prefer_file_axes();
  const UprightFrame read = upright_frame(mesh, hint);
  hint.file_axes = pose.rotation;
  const UprightFrame posed = upright_frame(arg::apply_pose(mesh, pose), hint);
  EXPECT_GT(posed.up.dot(pose.rotation * read.up), 0.999);
  EXPECT_GT(posed.up.dot(pose.rotation * Eigen::Vector3d::UnitY()), 0.999);
}

TEST(UprightFrame, UpAxisIsParsedOrRefused) {
  EXPECT_EQ(arg::parse_up_axis("+y"), Eigen::Vector3d::UnitY());
  EXPECT_EQ(arg::parse_up_axis("-Z"), -Eigen::Vector3d::UnitZ());
  EXPECT_EQ(arg::parse_up_axis(" x "), Eigen::Vector3d::UnitX());
  for (const char* bad : {"", "+", "up", "+w", "y+", "++y", "-yz"}) {
    try {
      arg::parse_up_axis(bad);
      ADD_FAILURE() << "'" << bad << "' was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("+x, -x, +y, -y, +z, -z"), std::string::npos) << bad;
    }
  }
}

}  // namespace
