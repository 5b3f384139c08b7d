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
    {"level_ratio", &Weights::level_ratio},
};

// The switches, each with its two words (off first) as the text writes them.
struct Switch {
  const char* name;
  bool Weights::*member;
  const char* off;
  const char* on;
};
constexpr Switch kSwitches[] = {
    {"norm", &Weights::l2, "l1", "l2"},
    {"tung", &Weights::tung_rule, "off", "on"},
    {"groups", &Weights::groups, "off", "on"},
};

// Readable names beside the paper's symbols, for readers without the paper at hand: each says
// what its weight weighs. The loss terms compare two nodes' areas, lengths (ranges of mu) and
// the spherical coordinates r, theta, phi of their barycentres; the sim terms count the area,
// length, volume, cords, curvature and colour they share. format_weights keeps the symbols, so
// stored text does not depend on the spelling.
struct Alias {
  const char* name;
  const char* symbol;
};
constexpr Alias kAliases[] = {
    {"loss_area", "alpha_l"},  {"loss_length", "beta_l"}, {"loss_radius", "gamma_l"},
    {"loss_theta", "delta_l"}, {"loss_phi", "eps_l"},     {"area", "alpha_s"},
    {"length", "beta_s"},      {"volume", "lambda_1"},    {"cords", "lambda_2"},
    {"curvature", "lambda_3"}, {"colour", "lambda_4"},    {"color", "lambda_4"},
};

// Every preset, each applied to the defaults (the `arg` preset: see weights.hpp). "color" is
// "colour" as American English spells it.
struct Preset {
  const char* name;
  void (*apply)(Weights&);
};
constexpr Preset kPresets[] = {
    {"arg", [](Weights&) {}},
    {"part",  // 0.2.0's graph weights: node against node, they find a part's kin better
     [](Weights& w) {
       w.lambda_2 = 1.0f;
       w.lambda_3 = 3.0f;
       w.level_ratio = 1.0f;
     }},
    {"mrg",  // Hilaga et al.: topology only, equal weights
     [](Weights& w) {
       w.alpha_l = w.beta_l = 0.5f;
       w.gamma_l = w.delta_l = w.eps_l = 0;
       w.alpha_s = w.beta_s = 0.5f;
       w.lambda_1 = w.lambda_2 = w.lambda_3 = w.lambda_4 = 0;
       w.graph = 1;
       w.panorama = w.spectrum = 0;
       w.graph_on_proxy = 1;
       w.level_ratio = 1;
       w.tung_rule = false;
       w.groups = true;
     }},
    {"graph",  // the augmented graph alone, without whole-shape terms
     [](Weights& w) {
       w.graph = 1;
       w.panorama = w.spectrum = 0;
       w.graph_on_proxy = 1;
     }},
    {"shape", [](Weights& w) { w.lambda_4 = 0; }},      // geometry and features, colour ignored
    {"colour", [](Weights& w) { w.lambda_4 = 5.0f; }},  // appearance first
    {"color", [](Weights& w) { w.lambda_4 = 5.0f; }},
};

bool is_mixing(const Field& f) {
  return f.member == &Weights::graph || f.member == &Weights::panorama ||
         f.member == &Weights::spectrum || f.member == &Weights::graph_on_proxy ||
         f.member == &Weights::level_ratio;
}

// The largest number of kMixingStep steps a mixing weight may take (its storage in SQL).
int max_steps(const Field& f) {
  if (f.member == &Weights::graph_on_proxy) return kMaxGraphOnProxySteps;
  return f.member == &Weights::level_ratio ? kMaxLevelRatioSteps : 255;
}

// The presets an error message names, "arg, part, ..., colour" ("color" is another spelling).
std::string preset_names() {
  std::string text;
  for (const Preset& p : kPresets)
    if (std::string_view(p.name) != "color") text.append(text.empty() ? "" : ", ").append(p.name);
  return text;
}

bool try_preset(std::string_view name, Weights& w) {
  for (const Preset& p : kPresets)
    if (name == p.name) {
      w = Weights{};
      p.apply(w);
      return true;
    }
  return false;
}

const WeightKey* find_key(std::string_view name) {
  for (const WeightKey& k : weight_keys())
    if (k.name == name) return &k;
  return nullptr;
}

// The keys an error message suggests: the symbols, then the readable names.
std::string expected_keys() {
  std::string symbols, names;
  for (const WeightKey& k : weight_keys()) {
    std::string& list = k.name == k.symbol ? symbols : names;
    list += (list.empty() ? "" : " ") + std::string(k.name);
  }
  return symbols + ", or a readable name: " + names;
}

// Sets the switch `symbol` from its word.
void set_switch(std::string_view symbol, const std::string& key, const std::string& value,
                Weights& w) {
  for (const Switch& s : kSwitches)
    if (symbol == s.name) {
      if (value == s.off)
        w.*s.member = false;
      else if (value == s.on)
        w.*s.member = true;
      else
        throw InputError("weights: " + key + "=" + value + " (expected " + s.off + " or " + s.on +
                         ")");
    }
}

// Sets the weight `symbol` from its number.
void set_number(std::string_view symbol, const std::string& key, const std::string& value,
                Weights& w) {
  for (const Field& f : kFields)
    if (symbol == f.name) {
      double x = parse_finite_number(value, key, kWhat);
      if (is_mixing(f)) {
        // Stored in a byte each (arg_weights keeps its 48 bytes): steps of kMixingStep.
        const double steps = std::round(x / kMixingStep);
        if (x < 0 || steps > max_steps(f) || std::fabs(x / kMixingStep - steps) > 1e-6)
          throw InputError("weights: " + key + "=" + value + " must be a multiple of 0.05 in [0, " +
                           (max_steps(f) == 255 ? "12.75" : "1") + "]");
        w.*f.member = mixing_weight(int(steps));
      } else {
        if (x < 0 || x > 1e6)
          throw InputError("weights: " + key + "=" + value + " must be in [0, 1e6]");
        w.*f.member = float(x);
      }
    }
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
  if (mixing_steps(w.level_ratio) > kMaxLevelRatioSteps)
    throw InputError(std::string(kWhat) + ": level_ratio must be at most 1");
  if (w.graph + w.panorama + w.spectrum <= 0)
    throw InputError(std::string(kWhat) +
                     ": at least one of graph, panorama, spectrum must be positive");
}

}  // namespace

float mixing_weight(int steps) {
  return float(steps * kMixingStep);
}

int grid_steps(std::string_view symbol) {
  for (const Field& f : kFields)
    if (symbol == f.name) return is_mixing(f) ? max_steps(f) : 0;
  return 0;
}

int mixing_steps(float weight) {
  return int(std::lround(double(weight) / kMixingStep));
}

const std::vector<WeightKey>& weight_keys() {
  static const std::vector<WeightKey> keys = [] {
    std::vector<WeightKey> k;
    for (const Field& f : kFields) k.push_back({f.name, f.name, {}});
    for (const Switch& s : kSwitches) k.push_back({s.name, s.name, {s.off, s.on}});
    for (const Alias& a : kAliases) k.push_back({a.name, a.symbol, {}});
    return k;
  }();
  return keys;
}

const std::vector<std::string_view>& weight_presets() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> n;
    for (const Preset& p : kPresets) n.push_back(p.name);
    return n;
  }();
  return names;
}

Weights weights_preset(std::string_view name) {
  Weights w;
  if (!try_preset(name, w))
    throw InputError(std::string(kWhat) + ": unknown preset \"" + std::string(name) +
                     "\" (expected one of " + preset_names() + ")");
  return w;
}

Weights parse_weights(std::string_view text) {
  Weights w = weights_preset("arg");
  auto pairs = split_key_values(text, kWhat);
  if (pairs.empty())
    throw InputError("weights: empty text (give a preset name or key=value pairs)");
  // The key that set each weight so far: a weight given twice, under one name or two, is an
  // error rather than a silent choice between the two values.
  std::vector<std::pair<std::string_view, std::string>> given;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto& [key, value] = pairs[i];
    if (value.empty()) {
      if (i != 0 || !try_preset(key, w))
        throw InputError("weights: \"" + key + "\" is not a preset (" + preset_names() + ") " +
                         (i != 0 ? "or the preset is not first" : "nor key=value"));
      continue;
    }
    const WeightKey* k = find_key(key);
    if (!k)
      throw InputError("weights: unknown key \"" + key + "\" (expected " + expected_keys() + ")");
    for (const auto& [symbol, earlier] : given)
      if (symbol == k->symbol)
        throw InputError(earlier == key ? "weights: " + key + " is given twice"
                                        : "weights: " + earlier + " and " + key + " both set " +
                                              std::string(k->symbol) + " (give it once)");
    given.emplace_back(k->symbol, key);
    if (k->words.empty())
      set_number(k->symbol, key, value, w);
    else
      set_switch(k->symbol, key, value, w);
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
  for (const Switch& s : kSwitches)
    out += std::string(s.name) + "=" + (w.*s.member ? s.on : s.off) + " ";
  out.pop_back();
  return out;
}

bool operator==(const Weights& a, const Weights& b) {
  for (const Field& f : kFields)
    if (a.*f.member != b.*f.member) return false;
  for (const Switch& s : kSwitches)
    if (a.*s.member != b.*s.member) return false;
  return true;
}

}  // namespace arg
