// Coordinate search over the loss, sim and mixing weights (the paper's future work: learnt
// weights).
#include "eval/weight_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace arg {

namespace {

struct Knob {
  const char* name;
  float Weights::*member;
  bool mixing;  // one of the terms' mixing, which --mixing-only searches
};

constexpr Knob kKnobs[] = {
    {"graph", &Weights::graph, true},        {"panorama", &Weights::panorama, true},
    {"spectrum", &Weights::spectrum, true},  {"graph_on_proxy", &Weights::graph_on_proxy, true},
    {"alpha_s", &Weights::alpha_s, false},   {"beta_s", &Weights::beta_s, false},
    {"lambda_1", &Weights::lambda_1, false}, {"lambda_2", &Weights::lambda_2, false},
    {"lambda_3", &Weights::lambda_3, false}, {"lambda_4", &Weights::lambda_4, false},
    {"alpha_l", &Weights::alpha_l, false},   {"beta_l", &Weights::beta_l, false},
    {"gamma_l", &Weights::gamma_l, false},   {"delta_l", &Weights::delta_l, false},
    {"eps_l", &Weights::eps_l, false},       {"level_ratio", &Weights::level_ratio, false},
};

bool valid(const Weights& w) {
  return w.alpha_s + w.beta_s + w.lambda_1 + w.lambda_2 + w.lambda_3 + w.lambda_4 > 0 &&
         w.graph + w.panorama + w.spectrum > 0;
}

// A weight kept on the grid of kMixingStep (the SQL type's byte or bits) rounded to it; other
// weights as they are.
float on_grid(const Knob& k, float value) {
  const int most = grid_steps(k.name);
  return most == 0 ? value : mixing_weight(std::clamp(mixing_steps(value), 0, most));
}

}  // namespace

bool is_mixing_weight(const char* name) {
  for (const Knob& k : kKnobs)
    if (std::string(name) == k.name) return k.mixing;
  return false;
}

Weights search_one_weight(const Weights& start, const std::string& name,
                          const std::vector<float>& values,
                          const std::function<double(const Weights&)>& objective) {
  const Knob* knob = nullptr;
  for (const Knob& k : kKnobs)
    if (name == k.name) knob = &k;
  if (!knob) throw std::invalid_argument("no weight '" + name + "' to search");
  if (values.empty()) throw std::invalid_argument("no values to try for " + name);
  Weights best = start;
  double best_score = 0;
  bool found = false;
  for (float value : values) {
    if (!(value >= 0)) throw std::invalid_argument(name + " must be at least 0");
    value = on_grid(*knob, value);
    Weights w = start;
    w.*knob->member = value;
    if (!valid(w)) continue;
    const double score = objective(w);
    if (!found || score > best_score) best = w, best_score = score, found = true;
  }
  return best;
}

Weights search_weights(const Weights& start, const std::function<double(const Weights&)>& objective,
                       int rounds, double min_gain,
                       const std::function<void(const std::string&)>& log, bool mixing_only) {
  Weights best = start;
  double best_score = objective(best);
  for (int round = 0; round < rounds; ++round) {
    bool changed = false;
    for (const Knob& k : kKnobs) {
      if (mixing_only && !k.mixing) continue;
      const float current = best.*k.member;
      float trials[3] = {current * 0.5f, current * 2.0f, current == 0 ? 0.1f : 0.0f};
      for (float& t : trials) t = on_grid(k, t);
      for (float value : trials) {
        if (value == current) continue;
        Weights w = best;
        w.*k.member = value;
        if (!valid(w)) continue;
        const double score = objective(w);
        if (score > best_score + min_gain) {
          if (log) {
            char line[160];
            std::snprintf(line, sizeof line, "round %d: %s %.4g -> %.4g, objective %.4f -> %.4f",
                          round + 1, k.name, double(best.*k.member), double(value), best_score,
                          score);
            log(line);
          }
          best = w, best_score = score, changed = true;
        }
      }
    }
    if (!changed) break;
  }
  return best;
}

Weights grid_search_mixing(const Weights& start,
                           const std::function<double(const Weights&)>& objective) {
  Weights best = start;
  double best_score = -1;
  // In steps of kMixingStep: about 1.3 times apart, finer than the objective's noise.
  for (int proxy : {20, 15, 10, 7, 5})
    for (int panorama : {10, 15, 20, 25, 30, 40, 50, 60, 80, 100, 120, 160})
      for (int spectrum : {0, 2, 3, 5, 7, 10, 15, 20, 25, 30, 40, 60}) {
        Weights w = start;
        w.graph = mixing_weight(20);
        w.panorama = mixing_weight(panorama);
        w.spectrum = mixing_weight(spectrum);
        w.graph_on_proxy = mixing_weight(proxy);
        const double score = objective(w);
        if (score > best_score) best = w, best_score = score;
      }
  return best;
}

}  // namespace arg
