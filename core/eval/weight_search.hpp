// Learning matching weights: a deterministic coordinate search that maximises an objective.
#pragma once

#include <functional>
#include <string>

#include "match/weights.hpp"

namespace arg {

// Starting from `start`, visits every weight in a fixed order and tries it multiplied by
// 0.5 and 2 (or set to 0.1 when it is 0, or to 0), keeping a change only when the objective
// grows by more than `min_gain`; repeats for `rounds` passes or until a pass changes nothing.
// `log` (optional) hears each accepted change. Deterministic for a deterministic objective.
Weights search_weights(const Weights& start, const std::function<double(const Weights&)>& objective,
                       int rounds = 3, double min_gain = 1e-4,
                       const std::function<void(const std::string&)>& log = {});

}  // namespace arg
