// Learning matching weights: a deterministic coordinate search that maximises an objective.
#pragma once

#include <functional>
#include <string>

#include "match/weights.hpp"

namespace arg {

// Starting from `start`, visits every weight in a fixed order (the mixing weights graph,
// panorama and spectrum first, then those of sim and of the loss) and tries it multiplied by
// 0.5 and 2 (or set to 0.1 when it is 0, or to 0), mixing weights rounded to their grid,
// keeping a change only when the objective grows by more than `min_gain`; repeats for
// `rounds` passes or until a pass changes nothing. `mixing_only` leaves the graph's own
// weights alone. `log` (optional) hears each accepted change. Deterministic for a
// deterministic objective.
Weights search_weights(const Weights& start, const std::function<double(const Weights&)>& objective,
                       int rounds = 3, double min_gain = 1e-4,
                       const std::function<void(const std::string&)>& log = {},
                       bool mixing_only = false);

// Tries every panorama weight in {0.5, 1, 1.5, 2, 3, 4, 6} with every spectrum weight in
// {0, 0.1, 0.25, 0.5, 1, 1.5, 2, 3} (graph weight 1, everything else as in `start`) and returns
// the best by `objective` (the first in that order on ties). Coarse on purpose: 56 choices of
// two numbers leave the training sets little to overfit.
Weights grid_search_mixing(const Weights& start,
                           const std::function<double(const Weights&)>& objective);

// Whether the named weight only mixes SIM's terms (so the graph matching needs no rerun).
bool is_mixing_weight(const char* name);

}  // namespace arg
