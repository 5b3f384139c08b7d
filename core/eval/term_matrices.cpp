// SIM over a set from its terms computed once.
#include "eval/term_matrices.hpp"

#include <algorithm>

#include "features/laplace_spectrum.hpp"
#include "features/panorama_descriptor.hpp"

namespace arg {

TermMatrices term_matrices(const std::vector<const ArgGraph*>& graphs) {
  TermMatrices m;
  const std::size_t n = m.n = graphs.size();
  m.flags.assign(n, 0), m.has_panorama.assign(n, 0), m.has_spectrum.assign(n, 0);
  m.panorama.assign(n * n, 0.0), m.spectrum.assign(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!graphs[i]) continue;
    m.flags[i] = graphs[i]->summary.flags;
    m.has_panorama[i] = !graphs[i]->panorama.empty();
    m.has_spectrum[i] = !graphs[i]->spectrum.empty();
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j || !graphs[i] || !graphs[j]) continue;
      const ArgGraph &a = *graphs[i], &b = *graphs[j];
      if (m.has_panorama[i] && m.has_panorama[j])
        m.panorama[i * n + j] = panorama_distance(a.panorama, b.panorama);
      if (m.has_spectrum[i] && m.has_spectrum[j])
        m.spectrum[i * n + j] = spectrum_distance(a.spectrum, b.spectrum);
    }
  return m;
}

TermWeights pair_term_weights(const TermMatrices& m, std::size_t i, std::size_t j,
                              const Weights& w) {
  return term_weights(w, m.flags[i] | m.flags[j], m.has_panorama[i] && m.has_panorama[j],
                      m.has_spectrum[i] && m.has_spectrum[j]);
}

double mixed_similarity(const TermMatrices& m, std::size_t i, std::size_t j, const Weights& w,
                        double graph) {
  const TermWeights t = pair_term_weights(m, i, j, w);
  const std::size_t k = i * m.n + j;
  const double panorama = t.panorama > 0 ? m.panorama[k] : 0.0;
  const double spectrum = t.spectrum > 0 ? m.spectrum[k] : 0.0;
  return std::clamp(mix_terms(t, t.graph > 0 ? graph : 0.0, panorama, spectrum), 0.0, 1.0);
}

}  // namespace arg
