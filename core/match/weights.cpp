// Presets, parsing, validation and printing of matching weights.
#include "match/weights.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "common/errors.hpp"
#include "common/key_values.hpp"

namespace arg {

namespace {

constexpr const char* kWhat = "weights";

struct Field {
  const char* name;
  float Weights::*member;
};
constexpr Field kFields[] = {
    {"alpha_l", &Weights::alpha_l},
    {"beta_l", &Weights::beta_l},
    {"gamma_l", &Weights::gamma_l},
    {"delta_l", &Weights::delta_l},
    {"eps_l", &Weights::eps_l},
    {"alpha_s", &Weights::alpha_s},
    {"beta_s", &Weights::beta_s},
    {"lambda_1", &Weights::lambda_1},
    {"lambda_2", &Weights::lambda_2},
    {"lambda_3", &Weights::lambda_3},
    {"lambda_4", &Weights::lambda_4},
    {"graph", &Weights::graph},
    {"panorama", &Weights::panorama},
    {"spectrum", &Weights::spectrum},
    {"graph_on_proxy", &Weights::graph_on_proxy},
};

bool is_mixing(const Field& f) {
  return f.member == &Weights::graph || f.member == &Weights::panorama ||
         f.member == &Weights::spectrum || f.member == &Weights::graph_on_proxy;
}

// The largest number of kMixingStep steps a mixing weight may take (its storage in SQL).
int max_steps(const Field& f) {
  return f.member == &Weights::graph_on_proxy ? kMaxGraphOnProxySteps : 255;
}

bool try_preset(std::string_view name, Weights& w) {
  const Weights arg;  // the defaults: see weights.hpp
  if (name == "arg") {
    w = arg;
  } else if (name == "mrg") {  // Hilaga et al.: topology only, equal weights
    w = Weights{};
    w.alpha_l = w.beta_l = 0.5f;
    w.gamma_l = w.delta_l = w.eps_l = 0;
    w.alpha_s = w.beta_s = 0.5f;
    w.lambda_1 = w.lambda_2 = w.lambda_3 = w.lambda_4 = 0;
    w.graph = 1;
    w.panorama = w.spectrum = 0;
    w.graph_on_proxy = 1;
    w.tung_rule = false;
    w.groups = true;
  } else if (name == "graph") {  // the augmented graph alone, without whole-shape terms
    w = arg;
    w.graph = 1;
    w.panorama = w.spectrum = 0;
    w.graph_on_proxy = 1;
  } else if (name == "shape") {  // geometry and features, colour ignored
    w = arg;
    w.lambda_4 = 0;
  } else if (name == "colour" || name == "color") {  // appearance first
    w = arg;
    w.lambda_4 = 5.0f;
  } else {
    return false;
  }
  return true;
}

void validate(const Weights& w) {
  for (const Field& f : kFields) {
    float x = w.*f.member;
    if (!std::isfinite(x) || x < 0)
      throw InputError(std::string(kWhat) + ": " + f.name + " must be finite and >= 0");
  }
  if (w.alpha_s + w.beta_s + w.lambda_1 + w.lambda_2 + w.lambda_3 + w.lambda_4 <= 0)
    throw InputError(std::string(kWhat) +
                     ": at least one of alpha_s, beta_s, lambda_1..lambda_4 must be positive");
  if (mixing_steps(w.graph_on_proxy) > kMaxGraphOnProxySteps)
    throw InputError(std::string(kWhat) + ": graph_on_proxy must be at most 1");
  if (w.graph + w.panorama + w.spectrum <= 0)
    throw InputError(std::string(kWhat) +
                     ": at least one of graph, panorama, spectrum must be positive");
}

}  // namespace

float mixing_weight(int steps) {
  return float(steps * kMixingStep);
}

int mixing_steps(float weight) {
  return int(std::lround(double(weight) / kMixingStep));
}

Weights weights_preset(std::string_view name) {
  Weights w;
  if (!try_preset(name, w))
    throw InputError(std::string(kWhat) + ": unknown preset \"" + std::string(name) +
                     "\" (expected arg, mrg, graph, shape or colour)");
  return w;
}

Weights parse_weights(std::string_view text) {
  Weights w = weights_preset("arg");
  auto pairs = split_key_values(text, kWhat);
  if (pairs.empty())
    throw InputError("weights: empty text (give a preset name or key=value pairs)");
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto& [key, value] = pairs[i];
    if (value.empty()) {
      if (i != 0 || !try_preset(key, w))
        throw InputError("weights: \"" + key +
                         "\" is not a preset (arg, mrg, graph, shape, colour) " +
                         (i != 0 ? "or the preset is not first" : "nor key=value"));
      continue;
    }
    if (key == "norm") {
      if (value == "l1")
        w.l2 = false;
      else if (value == "l2")
        w.l2 = true;
      else
        throw InputError("weights: norm=" + value + " (expected l1 or l2)");
      continue;
    }
    if (key == "groups") {
      if (value == "on")
        w.groups = true;
      else if (value == "off")
        w.groups = false;
      else
        throw InputError("weights: groups=" + value + " (expected on or off)");
      continue;
    }
    if (key == "tung") {
      if (value == "on")
        w.tung_rule = true;
      else if (value == "off")
        w.tung_rule = false;
      else
        throw InputError("weights: tung=" + value + " (expected on or off)");
      continue;
    }
    bool known = false;
    for (const Field& f : kFields)
      if (key == f.name) {
        double x = parse_finite_number(value, key, kWhat);
        if (is_mixing(f)) {
          // Stored in a byte each (arg_weights keeps its 48 bytes): steps of kMixingStep.
          const double steps = std::round(x / kMixingStep);
          if (x < 0 || steps > max_steps(f) || std::fabs(x / kMixingStep - steps) > 1e-6)
            throw InputError("weights: " + key + "=" + value +
                             " must be a multiple of 0.05 in [0, " +
                             (max_steps(f) == 255 ? "12.75" : "1") + "]");
          w.*f.member = mixing_weight(int(steps));
        } else {
          if (x < 0 || x > 1e6)
            throw InputError("weights: " + key + "=" + value + " must be in [0, 1e6]");
          w.*f.member = float(x);
        }
        known = true;
      }
    if (!known)
      throw InputError(
          "weights: unknown key \"" + key +
          "\" (expected alpha_l beta_l gamma_l delta_l eps_l alpha_s beta_s "
          "lambda_1..lambda_4 graph panorama spectrum graph_on_proxy norm tung groups)");
  }
  validate(w);
  return w;
}

std::string format_weights(const Weights& w) {
  std::string out;
  char buf[64];
  for (const Field& f : kFields) {
    // The shortest decimal that reads back as the same float: "0.3", not "0.300000012".
    const float x = w.*f.member;
    for (int digits = 6; digits <= 9; ++digits) {
      std::snprintf(buf, sizeof buf, "%s=%.*g ", f.name, digits, double(x));
      if (std::strtof(std::strchr(buf, '=') + 1, nullptr) == x) break;
    }
    out += buf;
  }
  out += w.l2 ? "norm=l2 " : "norm=l1 ";
  out += w.tung_rule ? "tung=on" : "tung=off";
  out += w.groups ? " groups=on" : " groups=off";
  return out;
}

bool operator==(const Weights& a, const Weights& b) {
  for (const Field& f : kFields)
    if (a.*f.member != b.*f.member) return false;
  return a.l2 == b.l2 && a.tung_rule == b.tung_rule && a.groups == b.groups;
}

}  // namespace arg
