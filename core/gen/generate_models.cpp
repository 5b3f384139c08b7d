// The project's own deterministic model generator: closed manifold meshes in labelled classes.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "gen/generate_models.hpp"

#include <algorithm>
#include <cstdio>

#include "common/errors.hpp"
#include "gen/marching_tetrahedra.hpp"
#include "gen/model_blueprints.hpp"
#include "mesh/collapse_short_edges.hpp"

namespace arg {
namespace {

struct ClassEntry {
  const char* name;
  int genus;
};

constexpr ClassEntry kClasses[] = {{"vase", 0},  {"cup", 1},     {"amphora", 2},
                                   {"torus", 1}, {"fourleg", 0}, {"human", 0},
                                   {"table", 0}, {"chair", 0},   {"octopus", 0}};

constexpr int kHumanPoses = 6;
constexpr double kCollapseShort = 0.3;
constexpr double kCollapseFlat = 0.75;
constexpr double kFlatCosine = 0.99;  // about 8 degrees

gen::Blueprint blueprint_for(const std::string& label, int variant, gen::SeededRandom& rng) {
  if (label == "vase") return gen::vase_blueprint(rng);
  if (label == "cup") return gen::cup_blueprint(rng);
  if (label == "amphora") return gen::amphora_blueprint(rng);
  if (label == "torus") return gen::torus_blueprint(rng);
  if (label == "fourleg") return gen::fourleg_blueprint(rng);
  // Poses go round with the variant so any five consecutive variants show five poses.
  if (label == "human")
    return gen::human_blueprint(rng, ((variant % kHumanPoses) + kHumanPoses) % kHumanPoses);
  if (label == "table") return gen::table_blueprint(rng);
  if (label == "chair") return gen::chair_blueprint(rng);
  return gen::octopus_blueprint(rng);
}

}  // namespace

std::vector<std::string> generator_classes() {
  std::vector<std::string> names;
  for (const auto& c : kClasses) names.emplace_back(c.name);
  return names;
}

GeneratedModel generate_model(const std::string& label, int variant, int resolution, bool colour) {
  const auto entry = std::find_if(std::begin(kClasses), std::end(kClasses),
                                  [&](const ClassEntry& c) { return label == c.name; });
  if (entry == std::end(kClasses)) throw InputError("unknown model class '" + label + "'");
  if (resolution < 8)
    throw InputError("generator resolution " + std::to_string(resolution) + " is below 8");
  if (resolution > 1024)
    throw LimitError("generator resolution " + std::to_string(resolution) + " is above 1024");

  gen::SeededRandom rng(gen::mix_seed(label, static_cast<std::uint64_t>(variant)));
  gen::Blueprint blueprint = blueprint_for(label, variant, rng);

  GeneratedModel model;
  char name[64];
  std::snprintf(name, sizeof name, "%s_%02d", entry->name, variant);
  model.name = name;
  model.label = label;
  model.genus = entry->genus;
  model.description = blueprint.description;
  // Marching tetrahedra leaves many slivers where the surface passes near a grid point;
  // collapsing edges under a fraction of a cell removes them, and longer edges go where the
  // surface is flat, so flat walls and table tops do not spend triangles that limbs need.
  const double step = gen::marching_grid_step(blueprint.solid.bounds, resolution);
  CollapseOptions collapse;
  collapse.min_length = kCollapseShort * step;
  collapse.flat_length = kCollapseFlat * step;
  collapse.flat_cosine = kFlatCosine;
  model.mesh =
      collapse_short_edges(gen::marching_tetrahedra(blueprint.solid, resolution), collapse);
  if (colour) {
    const Mesh& m = model.mesh;
    model.mesh.C.resize(m.F.rows(), 3);
    for (Eigen::Index t = 0; t < m.F.rows(); ++t) {
      Vec3 centroid;
      for (int c = 0; c < 3; ++c) {
        const auto v = m.F(t, c);
        centroid = centroid + Vec3{m.V(v, 0), m.V(v, 1), m.V(v, 2)};
      }
      const gen::Rgb rgb = blueprint.paint(centroid * (1.0 / 3.0));
      model.mesh.C(t, 0) = static_cast<float>(rgb.r);
      model.mesh.C(t, 1) = static_cast<float>(rgb.g);
      model.mesh.C(t, 2) = static_cast<float>(rgb.b);
    }
  }
  return model;
}

std::vector<GeneratedModel> generate_catalogue(int per_class, int resolution, bool colour) {
  if (per_class < 0) throw InputError("generate_catalogue: negative count per class");
  std::vector<GeneratedModel> models;
  models.reserve(static_cast<std::size_t>(per_class) * std::size(kClasses));
  for (const auto& c : kClasses)
    for (int v = 0; v < per_class; ++v)
      models.push_back(generate_model(c.name, v, resolution, colour));
  return models;
}

}  // namespace arg
