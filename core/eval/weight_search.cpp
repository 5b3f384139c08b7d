// Coordinate search over the loss and sim weights (the paper's future work: learnt weights).
#include "eval/weight_search.hpp"

#include <cstdio>

namespace arg {

Weights search_weights(const Weights& start, const std::function<double(const Weights&)>& objective,
                       int rounds, double min_gain,
                       const std::function<void(const std::string&)>& log) {
  struct Knob {
    const char* name;
    float Weights::*member;
  };
  static const Knob knobs[] = {
      {"alpha_s", &Weights::alpha_s},   {"beta_s", &Weights::beta_s},
      {"lambda_1", &Weights::lambda_1}, {"lambda_2", &Weights::lambda_2},
      {"lambda_3", &Weights::lambda_3}, {"lambda_4", &Weights::lambda_4},
      {"alpha_l", &Weights::alpha_l},   {"beta_l", &Weights::beta_l},
      {"gamma_l", &Weights::gamma_l},   {"delta_l", &Weights::delta_l},
      {"eps_l", &Weights::eps_l},
  };
  Weights best = start;
  double best_score = objective(best);
  for (int round = 0; round < rounds; ++round) {
    bool changed = false;
    for (const Knob& k : knobs) {
      const float current = best.*k.member;
      const float trials[] = {current * 0.5f, current * 2.0f, current == 0 ? 0.1f : 0.0f};
      for (float value : trials) {
        Weights w = best;
        w.*k.member = value;
        const double sims =
            w.alpha_s + w.beta_s + w.lambda_1 + w.lambda_2 + w.lambda_3 + w.lambda_4;
        if (!(sims > 0)) continue;
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

}  // namespace arg
