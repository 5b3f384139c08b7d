// The project's own deterministic model generator: closed manifold meshes in labelled classes.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

struct GeneratedModel {
  std::string name;   // e.g. "vase_2handles_03"
  std::string label;  // class, e.g. "vase2"
  int genus = 0;      // the genus the generator built in
  Mesh mesh;
};

// Class names the generator knows, in a fixed order.
std::vector<std::string> generator_classes();

// One model of class `label`; `variant` picks the deterministic variation inside the class.
// `resolution` is the marching grid size along the longest axis.
GeneratedModel generate_model(const std::string& label, int variant, int resolution = 48);

// The sample catalogue: `per_class` variants of every class (about 40 models by default).
std::vector<GeneratedModel> generate_catalogue(int per_class = 5, int resolution = 48);

}  // namespace arg
