// Weights of the loss (which nodes match) and of sim (how much a match is worth), with presets.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace arg {

// The defaults are the `arg` preset: the paper's section 6 loss and sim weights, feature weights
// (curvature and cords carry most of the class information, relative volume a little; colour
// counts as much as a and l together), and the mixing of the graph with the whole-shape terms
// (below).
struct Weights {
  // loss(m, n): alpha_l|a-a'| + beta_l|l-l'| + gamma_l|r-r'| + delta_l|theta-theta'| +
  // eps_l|phi-phi'|
  float alpha_l = 0.3f, beta_l = 0.15f, gamma_l = 0.15f, delta_l = 0.2f, eps_l = 0.2f;
  // sim(m, n): alpha_s min(a) + beta_s min(l) + lambda_1 min(v) + lambda_2 min(cords)
  //            + lambda_3 min(curvature) + lambda_4 min(colour)
  // Cords 0.5 and curvature 12 were chosen one weight at a time, the others held, in each
  // leave-one-set-out fold of SHREC 2007, SHREC 2011 and the PSB soups (argtool tune --only):
  // every fold settled there (0.1.0 had cords 1 and curvature 3). They rank whole models; a
  // part against parts is ranked better with 0.1.0's, which the `part` preset keeps.
  float alpha_s = 0.65f, beta_s = 0.35f;
  float lambda_1 = 0.3f, lambda_2 = 0.5f, lambda_3 = 12.0f, lambda_4 = 1.0f;
  // SIM = (graph SIM_graph + panorama D_panorama + spectrum D_spectrum) / (graph + panorama +
  // spectrum): the graph matching above, the view-based PANORAMA distance and the distance of
  // the Laplace-Beltrami spectra (each in [0, 1]); a term a value lacks (format 1) is left out,
  // and so is the spectra's when either model was built on its watertight proxy or is wide open.
  // The defaults (graph 1, panorama 2.5, spectrum 0.75, graph_on_proxy 0.75) were learnt on
  // SHREC 2007, SHREC 2011 and the PSB soups together, by the search whose leave-one-set-out
  // scores docs/BENCHMARKS.md reports (argtool tune --mixing-only --proxy-copies).
  float graph = 1.0f, panorama = 2.5f, spectrum = 0.75f;
  // The share of `graph` that counts when either model's graph was built on its watertight
  // proxy (a soup, a mesh in pieces): a proxy's Reeb graph is that of a shell closed at voxel
  // size, which tells classes apart less well than a surface's own graph, while the views see
  // the parts as they are. In [0, 1], steps of kMixingStep; 1 treats proxies like any mesh.
  // Learnt like the three above, on the training sets and on copies of them built on proxies
  // (argtool tune --proxy-copies): no proxy graph would be seen in training otherwise.
  float graph_on_proxy = 0.75f;
  // Each level's share of the graph's SIM is level_ratio times the share of the level above it
  // (r = 0 the coarsest): its matched pairs' sims and its nodes' self sims are weighed by
  // level_ratio^r. 1 weighs every level alike, as Hilaga's MRG does; below 1 the coarse levels,
  // where the whole shape is, count more than the fine ones, where its details are. Which
  // nodes match does not depend on it. In [0, 1], steps of kMixingStep.
  float level_ratio = 1.0f;
  bool l2 = false;        // squared differences in the loss instead of absolute ones
  bool tung_rule = true;  // Tung and Schmitt's extra consistency rule (off for Hilaga's MRG)
  bool groups = false;    // a node may match a group of nodes of its interval (Hilaga's MRG)
};

// One key of the weights text. The parser finds keys in this list and nowhere else, so a key it
// accepts cannot be missing from it (tests/unit/test_reference.cpp holds docs/REFERENCE.md to it).
struct WeightKey {
  std::string_view name;    // as written: a paper's symbol ("lambda_3") or its readable name
  std::string_view symbol;  // the key it sets, as format_weights writes it ("lambda_3")
  std::vector<std::string_view> words;  // a switch's values, off first ("l1", "l2"); a number: none
};

// Every key parse_weights accepts: the symbols in the order of format_weights, then the readable
// names (curvature for lambda_3, loss_area for alpha_l, ...).
const std::vector<WeightKey>& weight_keys();

// Every preset name weights_preset accepts ("color" as well as "colour").
const std::vector<std::string_view>& weight_presets();

// "arg", "part", "mrg", "graph", "shape" or "colour"; throws InputError for another name.
// "part" is the one arg_part_match and `argtool part` use by default: see Weights.
Weights weights_preset(std::string_view name);

// A preset name, or "key=value" pairs separated by spaces or commas, optionally after a preset
// ("shape lambda_4=0.1"). Keys (weight_keys()): alpha_l beta_l gamma_l delta_l eps_l alpha_s
// beta_s lambda_1..4 graph panorama spectrum graph_on_proxy level_ratio norm=l1|l2 tung=on|off
// groups=on|off, and readable names for the first eleven. Each weight at most once, under
// either name. Values finite and >= 0 (graph_on_proxy at most 1), at least one sim weight and
// one of graph, panorama, spectrum positive; graph_on_proxy and level_ratio at most 1.
Weights parse_weights(std::string_view text);

// graph, panorama and spectrum are multiples of this in [0, 255 steps]: the SQL type keeps
// each in one byte; graph_on_proxy and level_ratio in [0, 20 steps] (five bits each).
// mixing_weight(k) is the float for k steps; mixing_steps inverts it.
inline constexpr double kMixingStep = 0.05;
inline constexpr int kMaxGraphOnProxySteps = 20;
inline constexpr int kMaxLevelRatioSteps = 20;
float mixing_weight(int steps);
int mixing_steps(float weight);
// The most kMixingStep steps the weight `symbol` may take when it is kept on that grid (graph,
// panorama, spectrum: 255; graph_on_proxy, level_ratio: 20), 0 for a weight kept as any float.
int grid_steps(std::string_view symbol);

// Canonical text form; parse_weights(format_weights(w)) == w.
std::string format_weights(const Weights& w);

bool operator==(const Weights& a, const Weights& b);

}  // namespace arg
