// The project's own deterministic model generator: closed manifold meshes in labelled classes.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

struct GeneratedModel {
  std::string name;         // class and variant, e.g. "cup_03"
  std::string label;        // the class, e.g. "cup"
  int genus = 0;            // the genus the generator built in
  std::string description;  // a short phrase, e.g. "standing figure with arms raised"
  Mesh mesh;                // closed, manifold, outward oriented; per-face colour if asked
};

// Class names the generator knows, in a fixed order: vase, cup, amphora, torus, fourleg, human,
// table, chair, octopus.
std::vector<std::string> generator_classes();

// One model of class `label`; `variant` (any integer) picks the deterministic variation inside
// the class; `resolution` is the number of grid cells along the longest side of the model
// (8..1024; the built-in genus is guaranteed and tested for 32..64). The same arguments give a
// bit-identical mesh on every platform. Throws InputError for an unknown class or a resolution
// below 8, LimitError above 1024.
GeneratedModel generate_model(const std::string& label, int variant, int resolution = 48,
                              bool colour = true);

// The sample catalogue: `per_class` variants (0 .. per_class-1) of every class, in class order.
std::vector<GeneratedModel> generate_catalogue(int per_class = 5, int resolution = 48,
                                               bool colour = true);

}  // namespace arg
