// Learning matching weights: a deterministic coordinate search that maximises an objective.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "match/weights.hpp"

namespace arg {

// Starting from `start`, visits every weight in a fixed order (the mixing weights graph,
// panorama, spectrum and graph_on_proxy first, then those of sim and of the loss, then
// level_ratio) and tries it multiplied by 0.5 and 2 (or set to 0.1 when it is 0, or to 0),
// mixing weights and level_ratio rounded to their grid, keeping a change only when the objective
// grows by more than `min_gain`; repeats for `rounds` passes or until a pass changes nothing.
// `mixing_only` leaves the graph's own weights alone. `log` (optional) hears each accepted change.
// Deterministic for a deterministic objective.
Weights search_weights(const Weights& start, const std::function<double(const Weights&)>& objective,
                       int rounds = 3, double min_gain = 1e-4,
                       const std::function<void(const std::string&)>& log = {},
                       bool mixing_only = false);

// Tries every panorama weight in {0.5, 0.75, 1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8} with every
// spectrum weight in {0, 0.1, 0.15, 0.25, 0.35, 0.5, 0.75, 1, 1.25, 1.5, 2, 3} and every
// graph_on_proxy in {1, 0.75, 0.5, 0.35, 0.25} (graph weight 1, everything else as in `start`)
// and returns the best by `objective` (the first in that order on ties, so graph_on_proxy stays
// 1 when no training model was built on a proxy). A grid about 1.3 times apart: finer steps
// would only follow the noise of the training sets' scores.
Weights grid_search_mixing(const Weights& start,
                           const std::function<double(const Weights&)>& objective);

// The weight `name` (one the coordinate search visits: graph, panorama, spectrum,
// graph_on_proxy, alpha_s ... eps_l, level_ratio) set to each of `values` in turn, every other
// weight as in `start`; returns the best by `objective`, the first value listed on ties (list
// the value that leaves a term out first, so a term has to earn its weight). Mixing weights and
// level_ratio are rounded to their grid; a value that leaves no sim or no mixing weight positive is
// skipped. Throws std::invalid_argument for another name, no values or a value below 0.
Weights search_one_weight(const Weights& start, const std::string& name,
                          const std::vector<float>& values,
                          const std::function<double(const Weights&)>& objective);

// Whether the named weight only mixes SIM's terms (so the graph matching needs no rerun).
bool is_mixing_weight(const char* name);

}  // namespace arg
