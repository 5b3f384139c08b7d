// How SIM mixes its three terms.
#include "match/term_weights.hpp"

#include "graph/arg_graph.hpp"

namespace arg {

TermWeights term_weights(const Weights& w, std::uint16_t flags, bool panoramas, bool spectra) {
  TermWeights t;
  // In float, as SIM has always computed the proxy's share: the distance matrices stay as they
  // were to the bit.
  t.graph = (flags & kFlagProxy) != 0 ? w.graph * w.graph_on_proxy : w.graph;
  if (w.panorama > 0 && panoramas) t.panorama = w.panorama;
  const bool own_surfaces = (flags & (kFlagProxy | kFlagWideOpen)) == 0;
  if (w.spectrum > 0 && own_surfaces && spectra) t.spectrum = w.spectrum;
  if (t.graph + t.panorama + t.spectrum <= 0) t.graph = 1;
  return t;
}

TermShares term_shares(const TermWeights& t, double graph, double panorama, double spectrum) {
  const double total = t.graph + t.panorama + t.spectrum;
  return {t.graph * graph / total, t.panorama * panorama / total, t.spectrum * spectrum / total};
}

double mix_terms(const TermWeights& t, double graph, double panorama, double spectrum) {
  const TermShares s = term_shares(t, graph, panorama, spectrum);
  return s.graph + s.panorama + s.spectrum;
}

}  // namespace arg
