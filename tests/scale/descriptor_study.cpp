// How well a global descriptor finds the nearest models by SIM, and how tight a lower bound of
// SIM's graph term from level sums is. Reads the COPY rows that `argtool scale-gen` writes (id,
// museum, period, class, arg text), computes SIM for every pair, then for each model and each
// descriptor variant: the fraction of its 10 nearest by SIM that are among its C nearest by
// the descriptor's distance (recall@10 of a two-stage search with C candidates). Also the
// lower bound LB(M, N) <= G(M, N) of SIM's graph term G (README "Large catalogues"; a bound of
// the whole SIM would need the views and the spectrum as well): how often it is violated (it
// held on every pair for 0.1.0's G; later matching rules break it on a few), how close it
// comes, and how much an exact search by G could skip. And the second stage: recall@10 among
// the C nearest by arg_sketch_distance (search/shape_sketch.hpp), for graph mixes around the
// shipped one. Exits 0 either way: a study, not a test.
//
//   tests/scale/descriptor_study.sh SET [MAX_MODELS [QUERIES]]   (SET: a .copy or labels.csv)
//
// Every model is a query when there are at most 2,000 (or QUERIES is 0); otherwise QUERIES
// models spread over the file (default 20) query all the others.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include "common/parallel_for.hpp"
#include "graph/serialize.hpp"
#include "match/mpair.hpp"
#include "match/similarity.hpp"
#include "search/search_descriptor.hpp"
#include "search/shape_sketch.hpp"

namespace {

struct Model {
  std::string cls;
  arg::ArgGraph g;
  std::array<float, arg::kSearchDims> d{};
  arg::ShapeSketch sketch;
  // Level sums for the bound.
  std::vector<double> area, length, volume;                     // per level
  std::vector<std::array<double, arg::kCordBins>> cords;        // per level
  std::vector<std::array<double, arg::kCurvatureBins>> km, kg;  // per level
  std::vector<std::array<double, 3 * arg::kColourBins>> col;    // per level
  double self_nocolour = 0, self_colour_part = 0;               // self mass without / of colour
};

void level_sums(Model& m, const arg::Weights& w) {
  const arg::ArgGraph& g = m.g;
  const int L = g.levels() + 1;
  m.area.assign(L, 0), m.length.assign(L, 0), m.volume.assign(L, 0);
  m.cords.assign(L, {}), m.km.assign(L, {}), m.kg.assign(L, {}), m.col.assign(L, {});
  for (const arg::ArgNode& n : g.nodes) {
    const int r = n.level;
    m.area[r] += n.a, m.length[r] += n.l, m.volume[r] += n.v;
    for (int b = 0; b < arg::kCordBins; ++b) m.cords[r][b] += n.cords[b];
    for (int b = 0; b < arg::kCurvatureBins; ++b)
      m.km[r][b] += n.curv_mean[b], m.kg[r][b] += n.curv_gauss[b];
    for (int b = 0; b < 3 * arg::kColourBins; ++b) m.col[r][b] += n.colour[b];
    arg::Weights nc = w;
    nc.lambda_4 = 0;
    m.self_nocolour += arg::node_self_sim(n, nc);
    m.self_colour_part += w.lambda_4 * double(n.a);
  }
}

// Upper bound of SIM's numerator and SIM's denominator, from level sums only.
double lower_bound(const Model& x, const Model& y, const arg::Weights& w0) {
  arg::Weights w = w0;
  const bool colour = x.g.summary.has_colour && y.g.summary.has_colour;
  if (!colour) w.lambda_4 = 0;
  const int L = std::min(x.g.levels(), y.g.levels()) + 1;
  double ub = 0;
  for (int r = 0; r < L; ++r) {
    ub += w.alpha_s * std::min(x.area[r], y.area[r]) +
          w.beta_s * std::min(x.length[r], y.length[r]) +
          w.lambda_1 * std::min(x.volume[r], y.volume[r]);
    double c = 0, k = 0, col = 0;
    for (int b = 0; b < arg::kCordBins; ++b) c += std::min(x.cords[r][b], y.cords[r][b]);
    for (int b = 0; b < arg::kCurvatureBins; ++b)
      k += std::min(x.km[r][b], y.km[r][b]) + std::min(x.kg[r][b], y.kg[r][b]);
    for (int b = 0; b < 3 * arg::kColourBins; ++b) col += std::min(x.col[r][b], y.col[r][b]);
    ub += w.lambda_2 * c + w.lambda_3 * 0.5 * k + w.lambda_4 * col / 3.0;
  }
  const double den = 0.5 * (x.self_nocolour + y.self_nocolour +
                            (colour ? x.self_colour_part + y.self_colour_part : 0.0));
  if (!(den > 0)) return 0;
  return std::max(0.0, 1.0 - ub / den);
}

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> f;
  std::size_t p = 0;
  while (true) {
    std::size_t q = line.find('\t', p);
    f.push_back(line.substr(p, q == std::string::npos ? std::string::npos : q - p));
    if (q == std::string::npos) break;
    p = q + 1;
  }
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: descriptor_study FILE.copy [MAX_MODELS [QUERIES]]\n";
    return 2;
  }
  const std::size_t max_models = argc > 2 ? std::stoul(argv[2]) : 1000000;
  const std::size_t max_queries = argc > 3 ? std::stoul(argv[3]) : 20;
  const arg::Weights w;
  std::vector<Model> models;
  {
    std::ifstream in(argv[1]);
    std::string line;
    while (models.size() < max_models && std::getline(in, line)) {
      std::vector<std::string> f = split_tabs(line);
      Model m;
      m.cls = f.at(3);
      m.g = arg::deserialize_arg(arg::arg_from_text(f.at(4)));
      models.push_back(std::move(m));
    }
  }
  const std::size_t n = models.size();
  for (Model& m : models)
    m.d = arg::search_descriptor(m.g, w), m.sketch = arg::shape_sketch(m.g), level_sums(m, w);
  std::vector<std::size_t> qs;
  if (n <= 2000 || max_queries == 0) {
    for (std::size_t q = 0; q < n; ++q) qs.push_back(q);
  } else {
    for (std::size_t i = 0; i < max_queries; ++i) qs.push_back(i * n / max_queries);
  }
  const std::size_t nq = qs.size();
  std::fprintf(stderr, "%zu models, %zu queries; SIM of each query with every model...\n", n, nq);
  // sim[i * n + j]: SIM of query qs[i] and model j.
  // graph_sim: SIM's graph term alone, which the level-sum bound below is a bound of (the
  // whole-shape terms, the views and the spectrum, are not level sums).
  std::vector<float> sim(nq * n, 0.0f), graph_sim(nq * n, 0.0f);
  // second[m][i * n + j]: the sketch distance with graph mix mixes[m].
  const std::vector<double> mixes = {0.0, 0.02, arg::kSketchGraphMix, 0.1, 0.2};
  std::vector<std::vector<float>> second(mixes.size(), std::vector<float>(nq * n, 0.0f));
  const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  arg::parallel_for(nq * n, threads, [&](std::size_t k) {
    const std::size_t i = k / n, j = k % n;
    if (qs[i] == j) return;
    sim[k] = float(arg::arg_similarity(models[qs[i]].g, models[j].g, w));
    graph_sim[k] = float(arg::graph_similarity(models[qs[i]].g, models[j].g, w));
    for (std::size_t m = 0; m < mixes.size(); ++m)
      second[m][k] =
          float(arg::sketch_distance(models[qs[i]].sketch, models[j].sketch, w, mixes[m]));
  });

  // Descriptor variants: kept dimensions of the search descriptor and a norm.
  const int D = arg::kSearchDims;
  auto all = [&] {
    std::vector<int> v(D);
    std::iota(v.begin(), v.end(), 0);
    return v;
  }();
  auto without = [&](std::function<bool(int)> drop) {
    std::vector<int> v;
    for (int k = 0; k < D; ++k)
      if (!drop(k)) v.push_back(k);
    return v;
  };
  // Blocks of search_descriptor.hpp, in order: each variant leaves one out.
  struct Block {
    const char* name;
    int begin, end;
  };
  const Block blocks[] = {{"curvature", 0, arg::kSearchCountsAt},
                          {"node counts", arg::kSearchCountsAt, arg::kSearchAreasAt},
                          {"largest areas", arg::kSearchAreasAt, arg::kSearchPanoramaAt},
                          {"panorama", arg::kSearchPanoramaAt, arg::kSearchEigenAt},
                          {"eigenvalues", arg::kSearchEigenAt, arg::kSearchColourAt}};
  struct Variant {
    std::string name;
    std::vector<int> dims;
    int norm;                      // 1 taxicab, 2 Euclidean
    const float* pairs = nullptr;  // or a distance per pair, second[m]
  };
  std::vector<Variant> variants = {{"all, taxicab", all, 1}, {"all, Euclidean", all, 2}};
  for (const Block& b : blocks)  // colour is left in: no labelled set has colour
    variants.push_back({std::string("without ") + b.name + ", taxicab",
                        without([&](int k) { return k >= b.begin && k < b.end; }), 1});
  std::vector<int> cands;
  for (int c : {10, 20, 50, 100, 200, 500, 1000, 3000})
    if (std::size_t(c) < n) cands.push_back(c);
  const int K = 10;
  std::printf("descriptor variant (dims)                      ");
  for (int c : cands) std::printf("  C=%-4d", c);
  std::printf("   (recall@10 of the two-stage search, mean over %zu queries)\n", nq);
  // The header's stored global descriptor (48 floats: D2, cords, statistics), for comparison.
  variants.push_back({"header global (48), taxicab", {}, 1});
  // The second stage, by the sketch; the shipped graph mix is marked.
  for (std::size_t m = 0; m < mixes.size(); ++m) {
    char name[80];
    std::snprintf(name, sizeof name, "sketch, graph mix %.2f%s", mixes[m],
                  mixes[m] == arg::kSketchGraphMix ? " (shipped)" : "");
    variants.push_back({name, all, 1, second[m].data()});
  }
  for (const Variant& v : variants) {
    std::vector<double> recall(cands.size(), 0);
    const bool header = v.dims.empty();
    const std::size_t dims =
        v.pairs ? arg::kSketchGraphDims + arg::kPanoramaSize + arg::kSpectrumSize : v.dims.size();
    for (std::size_t qi = 0; qi < nq; ++qi) {
      const std::size_t q = qs[qi];
      const float* row = &sim[qi * n];
      std::vector<int> by_sim(n - 1), by_d(n - 1);
      std::vector<double> dist(n);
      for (std::size_t j = 0, t = 0; j < n; ++j) {
        if (j == q) continue;
        by_sim[t] = by_d[t] = int(j), ++t;
        double s = 0;
        if (v.pairs) {
          s = v.pairs[qi * n + j];
        } else if (header) {
          for (int k = 0; k < arg::kGlobalDims; ++k)
            s += std::fabs(double(models[q].g.global[k]) - models[j].g.global[k]);
        } else {
          for (int k : v.dims) {
            const double e = double(models[q].d[k]) - models[j].d[k];
            s += v.norm == 1 ? std::fabs(e) : e * e;
          }
        }
        dist[j] = s;
      }
      std::partial_sort(by_sim.begin(), by_sim.begin() + K, by_sim.end(),
                        [&](int a, int b) { return row[a] != row[b] ? row[a] < row[b] : a < b; });
      std::sort(by_d.begin(), by_d.end(),
                [&](int a, int b) { return dist[a] != dist[b] ? dist[a] < dist[b] : a < b; });
      for (std::size_t c = 0; c < cands.size(); ++c) {
        const std::size_t C = std::min<std::size_t>(cands[c], n - 1);
        std::vector<int> top(by_d.begin(), by_d.begin() + C);
        std::sort(top.begin(), top.end());
        int hit = 0;
        for (int k = 0; k < K; ++k) hit += std::binary_search(top.begin(), top.end(), by_sim[k]);
        recall[c] += hit / double(K);
      }
    }
    std::printf("%-40s (%4zu)", v.name.c_str(), header ? std::size_t(arg::kGlobalDims) : dims);
    for (double r : recall) std::printf("  %.4f", r / double(nq));
    std::printf("\n");
  }

  // The lower bound.
  std::size_t violations = 0, pairs = 0;
  double ratio = 0, gap = 0, skippable = 0;
  for (std::size_t qi = 0; qi < nq; ++qi) {
    const std::size_t q = qs[qi];
    std::vector<float> s10;
    std::vector<double> lb(n);
    for (std::size_t j = 0; j < n; ++j) {
      if (j == q) continue;
      lb[j] = lower_bound(models[q], models[j], w);
      const double s = graph_sim[qi * n + j];
      if (lb[j] > s + 1e-6) ++violations;
      if (s > 0) ratio += lb[j] / s, gap += s - lb[j], ++pairs;
      s10.push_back(float(s));
    }
    std::nth_element(s10.begin(), s10.begin() + (K - 1), s10.end());
    const double tenth = s10[K - 1];
    std::size_t skip = 0;
    for (std::size_t j = 0; j < n; ++j)
      if (j != q && lb[j] > tenth) ++skip;
    skippable += double(skip) / double(n - 1);
  }
  std::printf(
      "lower bound LB(M,N) of SIM's graph term from level sums: %zu violations of LB <= "
      "graph term in %zu pairs\n",
      violations, nq * (n - 1));
  std::printf("  mean LB / SIM %.3f, mean SIM - LB %.3f\n", ratio / pairs, gap / pairs);
  std::printf(
      "  share of models an exact search by the graph term could skip (LB > its 10th "
      "nearest): %.4f\n",
      skippable / nq);
  return 0;
}
