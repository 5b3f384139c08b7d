// How the first stage's block scales were chosen: leave-one-set-out over the labelled sets.
// Reads one COPY file a set (`argtool scale-gen` rows), computes SIM for every pair and each
// block's taxicab distance, then tries every multiplier in {1/2, 1/sqrt 2, 1, sqrt 2, 2} of the
// shipped scale of four blocks (curvature, node counts, largest areas, eigenvalues) against the
// fifth, the panorama (only ratios change a ranking; no labelled set has colour) and scores
// recall@10 among the 20 nearest by the descriptor. For each set it
// prints the multipliers the other sets choose and what they score on it (held out), then the
// choice of all sets together (a training score) and the shipped scales' scores.
//
//   tests/scale/descriptor_study.sh --tune A.copy B.copy [C.copy ...]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "common/parallel_for.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "search/search_descriptor.hpp"

namespace {

constexpr int kBlocks = 5, kCandidates = 20, kNearest = 10;
constexpr double kMultipliers[] = {0.5, 0.7071067811865476, 1.0, 1.4142135623730951, 2.0};
constexpr int kSteps = 5, kCombos = kSteps * kSteps * kSteps * kSteps;
constexpr int kFixed = 3;  // the panorama's scale stays
const char* kBlockNames[kBlocks] = {"curvature", "counts", "areas", "panorama", "eigenvalues"};

// First and one-past-last dimension of each block (search_descriptor.hpp).
constexpr std::array<std::array<int, 2>, kBlocks> kRanges = {
    {{0, arg::kSearchCountsAt},
     {arg::kSearchCountsAt, arg::kSearchAreasAt},
     {arg::kSearchAreasAt, arg::kSearchPanoramaAt},
     {arg::kSearchPanoramaAt, arg::kSearchEigenAt},
     {arg::kSearchEigenAt, arg::kSearchColourAt}}};

// One labelled set: each block's distance for every pair, and each model's ten nearest by SIM.
struct Set {
  std::string name;
  std::size_t n = 0;
  std::vector<std::vector<float>> block;  // [b][i * n + j]
  std::vector<std::array<int, kNearest>> nearest;
};

Set load(const std::string& path, int threads) {
  Set s;
  s.name = path;
  std::vector<arg::ArgGraph> g;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    g.push_back(arg::deserialize_arg(arg::arg_from_text(line.substr(line.rfind('\t') + 1))));
  const std::size_t n = s.n = g.size();
  if (n <= std::size_t(kCandidates)) throw std::runtime_error(path + ": too few models");
  const arg::Weights w;
  std::vector<std::array<float, arg::kSearchDims>> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = arg::search_descriptor(g[i], w);
  std::vector<double> sim(n * n, 0.0);
  arg::parallel_for(n * n, threads, [&](std::size_t k) {
    const std::size_t i = k / n, j = k % n;
    if (i < j) sim[k] = sim[j * n + i] = arg::arg_similarity(g[i], g[j], w);  // symmetric
  });
  s.block.assign(kBlocks, std::vector<float>(n * n, 0.0f));
  for (int b = 0; b < kBlocks; ++b)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        double t = 0;
        for (int k = kRanges[std::size_t(b)][0]; k < kRanges[std::size_t(b)][1]; ++k)
          t += std::fabs(double(d[i][std::size_t(k)]) - d[j][std::size_t(k)]);
        s.block[std::size_t(b)][i * n + j] = float(t);
      }
  s.nearest.resize(n);
  std::vector<int> order;
  for (std::size_t q = 0; q < n; ++q) {
    order.clear();
    for (std::size_t j = 0; j < n; ++j)
      if (j != q) order.push_back(int(j));
    std::partial_sort(order.begin(), order.begin() + kNearest, order.end(), [&](int a, int b) {
      return sim[q * n + std::size_t(a)] != sim[q * n + std::size_t(b)]
                 ? sim[q * n + std::size_t(a)] < sim[q * n + std::size_t(b)]
                 : a < b;
    });
    std::copy(order.begin(), order.begin() + kNearest, s.nearest[q].begin());
  }
  return s;
}

std::array<double, kBlocks> multipliers(int combo) {
  std::array<double, kBlocks> m{};
  for (int b = 0; b < kBlocks; ++b) {
    if (b == kFixed) {
      m[std::size_t(b)] = 1.0;
      continue;
    }
    m[std::size_t(b)] = kMultipliers[combo % kSteps];
    combo /= kSteps;
  }
  return m;
}

// How far a choice is from the shipped scales: ties go to the nearest.
double distance_from_shipped(int combo) {
  double t = 0;
  for (double x : multipliers(combo)) t += std::fabs(std::log(x));
  return t;
}

// Mean recall@10 among the kCandidates nearest by the scaled descriptor.
double recall(const Set& s, const std::array<double, kBlocks>& m) {
  const std::size_t n = s.n;
  std::vector<double> dist(n);
  std::vector<int> order;
  double total = 0;
  for (std::size_t q = 0; q < n; ++q) {
    order.clear();
    for (std::size_t j = 0; j < n; ++j) {
      if (j == q) continue;
      double t = 0;
      for (int b = 0; b < kBlocks; ++b) t += m[std::size_t(b)] * s.block[std::size_t(b)][q * n + j];
      dist[j] = t;
      order.push_back(int(j));
    }
    std::nth_element(order.begin(), order.begin() + (kCandidates - 1), order.end(),
                     [&](int a, int b) {
                       return dist[std::size_t(a)] != dist[std::size_t(b)]
                                  ? dist[std::size_t(a)] < dist[std::size_t(b)]
                                  : a < b;
                     });
    std::sort(order.begin(), order.begin() + kCandidates);
    int hit = 0;
    for (int k : s.nearest[q])
      hit += std::binary_search(order.begin(), order.begin() + kCandidates, k);
    total += hit / double(kNearest);
  }
  return total / double(n);
}

void print_choice(const char* label, const std::array<double, kBlocks>& m) {
  std::printf("%s", label);
  for (int b = 0; b < kBlocks; ++b) std::printf(" %s x%g", kBlockNames[b], m[std::size_t(b)]);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: descriptor_tuning A.copy B.copy [C.copy ...]\n";
    return 2;
  }
  const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<Set> sets;
  for (int a = 1; a < argc; ++a) {
    std::fprintf(stderr, "%s: SIM of every pair...\n", argv[a]);
    sets.push_back(load(argv[a], threads));
  }
  // score[c][s]: combo c on set s.
  std::vector<std::vector<double>> score(kCombos, std::vector<double>(sets.size()));
  for (int c = 0; c < kCombos; ++c)
    for (std::size_t s = 0; s < sets.size(); ++s)
      score[std::size_t(c)][s] = recall(sets[s], multipliers(c));
  auto best_on = [&](std::size_t left_out) {
    int best = 0;
    double best_mean = -1;
    for (int c = 0; c < kCombos; ++c) {
      double mean = 0;
      for (std::size_t s = 0; s < sets.size(); ++s)
        if (s != left_out) mean += score[std::size_t(c)][s];
      if (mean > best_mean + 1e-12 ||
          (mean > best_mean - 1e-12 && distance_from_shipped(c) < distance_from_shipped(best)))
        best_mean = std::max(mean, best_mean), best = c;
    }
    return best;
  };
  std::printf(
      "recall@%d among the %d nearest by the descriptor; multipliers of the shipped "
      "scales\n",
      kNearest, kCandidates);
  for (std::size_t h = 0; h < sets.size(); ++h) {
    const int c = best_on(h);
    std::printf("held out %s: %.4f with", sets[h].name.c_str(), score[std::size_t(c)][h]);
    print_choice(" (chosen on the others:", multipliers(c));
    std::printf(")\n");
  }
  const int all = best_on(sets.size());
  print_choice("all sets together (training):", multipliers(all));
  std::printf("\n");
  int shipped = 0;
  while (distance_from_shipped(shipped) > 0) ++shipped;
  for (std::size_t s = 0; s < sets.size(); ++s)
    std::printf("  %s: chosen %.4f, shipped %.4f\n", sets[s].name.c_str(),
                score[std::size_t(all)][s], score[std::size_t(shipped)][s]);
  return 0;
}
