// Tests of the model generator: every class is a closed oriented manifold of its declared genus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "gen/generate_models.hpp"
#include "gen/implicit_solid.hpp"
#include "gen/marching_tetrahedra.hpp"
#include "gen/perturb_mesh.hpp"
#include "gen/portable_math.hpp"
#include "io/write_mesh.hpp"
#include "test_mesh_inspection.hpp"

namespace arg {
namespace {

using test::inspect;
using test::Inspection;

// Models are generated once and shared by the tests that look at them.
const GeneratedModel& model(const std::string& label, int variant, int resolution) {
  static std::map<std::tuple<std::string, int, int>, GeneratedModel> cache;
  const auto key = std::make_tuple(label, variant, resolution);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, generate_model(label, variant, resolution)).first;
  return it->second;
}

struct Case {
  std::string label;
  int variant;
  int resolution;
};

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const auto& label : generator_classes()) {
    for (int v = 0; v < 6; ++v) cases.push_back({label, v, 32});  // six: every human pose
    for (int v = 0; v < 3; ++v) cases.push_back({label, v, 48});
  }
  return cases;
}

// Inspections are cached too: several tests read each one.
const Inspection& inspection(const std::string& label, int variant, int resolution) {
  static std::map<std::tuple<std::string, int, int>, Inspection> cache;
  const auto key = std::make_tuple(label, variant, resolution);
  auto it = cache.find(key);
  if (it == cache.end())
    it = cache.emplace(key, inspect(model(label, variant, resolution).mesh)).first;
  return it->second;
}

class GeneratedModelTopology : public testing::TestWithParam<Case> {
 protected:
  const GeneratedModel& m() const {
    return model(GetParam().label, GetParam().variant, GetParam().resolution);
  }
  const Inspection& r() const {
    return inspection(GetParam().label, GetParam().variant, GetParam().resolution);
  }
};

TEST_P(GeneratedModelTopology, IsClosedEveryEdgeBetweenExactlyTwoTriangles) {
  EXPECT_GT(r().faces, 0);
  EXPECT_TRUE(r().every_edge_has_two_triangles);
}

TEST_P(GeneratedModelTopology, IsAConsistentlyOrientedManifold) {
  EXPECT_TRUE(r().every_directed_edge_once);
  EXPECT_TRUE(r().every_fan_is_one_cycle);
  EXPECT_TRUE(r().every_vertex_used);
}

TEST_P(GeneratedModelTopology, IsOneConnectedPiece) {
  EXPECT_EQ(r().components, 1);
}

TEST_P(GeneratedModelTopology, HasNoDegenerateTriangle) {
  EXPECT_GT(r().smallest_area, 0.0);
}

TEST_P(GeneratedModelTopology, EulerCharacteristicMatchesTheDeclaredGenus) {
  EXPECT_EQ(r().euler(), 2 - 2 * m().genus) << m().name << " at " << GetParam().resolution;
}

TEST_P(GeneratedModelTopology, FacesPointOutwardsSoTheVolumeIsPositive) {
  EXPECT_GT(r().signed_volume, 0.0);
}

TEST_P(GeneratedModelTopology, IsPaintedOneColourPerTriangleInTheUnitRange) {
  const Mesh& mesh = m().mesh;
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_GE(mesh.C.minCoeff(), 0.0f);
  EXPECT_LE(mesh.C.maxCoeff(), 1.0f);
}

INSTANTIATE_TEST_SUITE_P(EveryClass, GeneratedModelTopology, testing::ValuesIn(all_cases()),
                         [](const testing::TestParamInfo<Case>& info) {
                           return info.param.label + "_" + std::to_string(info.param.variant) +
                                  "_at_" + std::to_string(info.param.resolution);
                         });

TEST(Generator, KnowsNineClassesInAFixedOrder) {
  EXPECT_EQ(generator_classes(),
            (std::vector<std::string>{"vase", "cup", "amphora", "torus", "fourleg", "human",
                                      "table", "chair", "octopus"}));
}

TEST(Generator, VaseWithoutHandleHasGenusZero) {
  const GeneratedModel& vase = model("vase", 0, 48);
  EXPECT_EQ(vase.genus, 0);
  EXPECT_EQ(inspection("vase", 0, 48).euler(), 2);
}

TEST(Generator, CupWithOneHandleHasGenusOne) {
  const GeneratedModel& cup = model("cup", 0, 48);
  EXPECT_EQ(cup.genus, 1);
  EXPECT_EQ(inspection("cup", 0, 48).euler(), 0);
}

TEST(Generator, AmphoraWithTwoHandlesHasGenusTwo) {
  const GeneratedModel& amphora = model("amphora", 0, 48);
  EXPECT_EQ(amphora.genus, 2);
  EXPECT_EQ(inspection("amphora", 0, 48).euler(), -2);
}

TEST(Generator, TorusHasGenusOneAndFiguresAndFurnitureGenusZero) {
  EXPECT_EQ(model("torus", 0, 48).genus, 1);
  for (const char* label : {"fourleg", "human", "table", "chair", "octopus"})
    EXPECT_EQ(model(label, 0, 48).genus, 0) << label;
}

TEST(Generator, ModelNamesJoinClassAndTwoDigitVariant) {
  const GeneratedModel& cup = model("cup", 3, 32);
  EXPECT_EQ(cup.name, "cup_03");
  EXPECT_EQ(cup.label, "cup");
  EXPECT_FALSE(cup.description.empty());
}

TEST(Generator, GeneratingTwiceGivesByteIdenticalMeshes) {
  for (const auto& label : generator_classes()) {
    const GeneratedModel a = generate_model(label, 4, 32);
    const GeneratedModel b = generate_model(label, 4, 32);
    EXPECT_EQ(write_off(a.mesh), write_off(b.mesh)) << label;
    EXPECT_TRUE(a.mesh.V == b.mesh.V) << label;
  }
}

TEST(Generator, VariantsOfAClassDifferFromEachOther) {
  for (const auto& label : generator_classes()) {
    std::set<std::string> seen;
    for (int v = 0; v < 4; ++v) seen.insert(write_off(model(label, v, 32).mesh));
    EXPECT_EQ(seen.size(), 4u) << label;
  }
}

TEST(Generator, FinerResolutionGivesMoreTriangles) {
  EXPECT_GT(model("cup", 0, 48).mesh.F.rows(), model("cup", 0, 32).mesh.F.rows());
}

TEST(Generator, ColourCanBeLeftOut) {
  const GeneratedModel plain = generate_model("chair", 0, 32, false);
  EXPECT_FALSE(plain.mesh.has_colour());
  EXPECT_TRUE(plain.mesh.V == model("chair", 0, 32).mesh.V);
}

TEST(Generator, RejectsUnknownClassesAndUnusableResolutions) {
  EXPECT_THROW(generate_model("teapot", 0), InputError);
  EXPECT_THROW(generate_model("cup", 0, 4), InputError);
  EXPECT_THROW(generate_model("cup", 0, 5000), LimitError);
}

TEST(GeneratorCatalogue, HoldsEveryClassInOrderWithFiveToThirtyThousandTrianglesEach) {
  const std::vector<GeneratedModel> catalogue = generate_catalogue();
  const std::vector<std::string> classes = generator_classes();
  ASSERT_EQ(catalogue.size(), 5 * classes.size());
  for (std::size_t i = 0; i < catalogue.size(); ++i) {
    const GeneratedModel& m = catalogue[i];
    EXPECT_EQ(m.label, classes[i / 5]);
    EXPECT_EQ(m.name, classes[i / 5] + "_0" + std::to_string(i % 5));
    EXPECT_GE(m.mesh.F.rows(), 5000) << m.name;
    EXPECT_LE(m.mesh.F.rows(), 30000) << m.name;
  }
}

TEST(GeneratorCatalogue, CountPerClassIsHonoured) {
  EXPECT_EQ(generate_catalogue(1, 16).size(), generator_classes().size());
  EXPECT_TRUE(generate_catalogue(0).empty());
  EXPECT_THROW(generate_catalogue(-1), InputError);
}

TEST(GeneratorMarching, ASphereBecomesAClosedSphereOfTheRightRadius) {
  const Mesh mesh = gen::marching_tetrahedra(gen::sphere({0.1, -0.2, 0.3}, 1.0), 40);
  const Inspection r = inspect(mesh);
  EXPECT_TRUE(r.every_edge_has_two_triangles);
  EXPECT_TRUE(r.every_directed_edge_once);
  EXPECT_EQ(r.euler(), 2);
  EXPECT_NEAR(r.signed_volume, 4.0 / 3.0 * gen::kPi, 0.02 * 4.0 / 3.0 * gen::kPi);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    EXPECT_NEAR((mesh.V.row(v) - Eigen::RowVector3d(0.1, -0.2, 0.3)).norm(), 1.0, 0.01);
}

TEST(GeneratorMarching, AFieldZeroExactlyOnGridPointsStillGivesAClosedManifold) {
  // The plane z = 0 through whole layers of grid points, capped to a slab: every sample on
  // those layers is exactly zero and must be nudged to one side.
  gen::Solid slab{
      [](const Vec3& p) {
        return std::max({std::fabs(p.z) - 0.5, std::fabs(p.x) - 1.0, std::fabs(p.y) - 1.0});
      },
      {{-1, -1, -0.5}, {1, 1, 0.5}}};
  const Inspection r = inspect(gen::marching_tetrahedra(slab, 8));
  EXPECT_TRUE(r.every_edge_has_two_triangles);
  EXPECT_TRUE(r.every_directed_edge_once);
  EXPECT_TRUE(r.every_fan_is_one_cycle);
  EXPECT_EQ(r.euler(), 2);
  EXPECT_GT(r.smallest_area, 0.0);
}

TEST(GeneratorPortableMath, SineAndCosineAgreeWithTheLibraryToRoundoff) {
  for (double x = -20.0; x <= 20.0; x += 0.0137) {
    EXPECT_NEAR(gen::portable_sin(x), std::sin(x), 1e-15);
    EXPECT_NEAR(gen::portable_cos(x), std::cos(x), 1e-15);
  }
}

TEST(GeneratorPerturbation, KeepsConnectivityAndColourAndIsReproducible) {
  const Mesh& original = model("fourleg", 0, 32).mesh;
  const Mesh a = perturb_mesh(original, 7, 0.1);
  const Mesh b = perturb_mesh(original, 7, 0.1);
  const Mesh c = perturb_mesh(original, 8, 0.1);
  EXPECT_TRUE(a.F == original.F);
  EXPECT_TRUE(a.C == original.C);
  EXPECT_EQ(write_off(a), write_off(b));
  EXPECT_NE(write_off(a), write_off(c));
  EXPECT_GT(inspect(a).signed_volume, 0.0);
}

TEST(GeneratorPerturbation, WithoutNoiseIsARotationAndUniformScale) {
  const Mesh& original = model("table", 1, 32).mesh;
  const Mesh moved = perturb_mesh(original, 3, 0.0);
  // Every edge scales by the same factor, and the factor is in [0.5, 2].
  double ratio = 0;
  for (Eigen::Index t = 0; t < original.F.rows(); t += 97) {
    const double before =
        (original.V.row(original.F(t, 0)) - original.V.row(original.F(t, 1))).norm();
    const double after = (moved.V.row(moved.F(t, 0)) - moved.V.row(moved.F(t, 1))).norm();
    if (ratio == 0) ratio = after / before;
    EXPECT_NEAR(after / before, ratio, 1e-9 * ratio);
  }
  EXPECT_GE(ratio, 0.5);
  EXPECT_LE(ratio, 2.0);
  EXPECT_NEAR(inspect(moved).signed_volume, inspect(original).signed_volume * ratio * ratio * ratio,
              1e-9 * inspect(moved).signed_volume);
  EXPECT_THROW(perturb_mesh(original, 3, -1.0), InputError);
}

}  // namespace
}  // namespace arg
