// Branching generated models as a ranking sees them: built, stored and read back.
#pragma once

#include <vector>

#include "gen/generate_models.hpp"
#include "graph/serialize.hpp"
#include "pipeline/build_arg.hpp"

namespace arg::test {

// Two human figures, a four-legged animal and an octopus with colour, a cup and a chair without;
// read back from format 3, so their histograms are byte codes.
inline const std::vector<ArgGraph>& stored_graphs() {
  static const std::vector<ArgGraph> all = [] {
    std::vector<ArgGraph> g;
    const char* classes[] = {"human", "human", "fourleg", "octopus", "cup", "chair"};
    for (int k = 0; k < 6; ++k) {
      const GeneratedModel m = generate_model(classes[k], k, 32, /*colour=*/k < 4);
      g.push_back(deserialize_arg(serialize_arg(build_arg(m.mesh))));
    }
    return g;
  }();
  return all;
}

}  // namespace arg::test
