// An inverted file against a navigable graph (HNSW) under the sketch distance: for each, how
// much of SIM's ten nearest are among the 25 candidates it hands to SIM (arg.ivf_candidates'
// default), and what it cost in distances computed. Decides the index's structure by
// measurement. Exits 0 either way: a study, not a test.
//
//   tests/scale/descriptor_study.sh --hnsw ROWS.copy N QUERIES.copy [POOL]
//
// ROWS.copy: scale-gen rows, the first N read; QUERIES.copy: the query rows. With POOL (the
// number of values ROWS.copy's rows are jittered copies of, in turn), the copies of each
// query's own value are left out, so that its nearest are other models' (held out).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numeric>
#include <queue>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "common/parallel_for.hpp"
#include "common/random.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "sampled_centres.hpp"
#include "search/coarse_sketch.hpp"
#include "search/sketch_cells.hpp"

namespace {

struct Row {
  long long id;
  std::string text;
};

std::vector<Row> read_rows(const char* path, std::size_t limit) {
  std::vector<Row> rows;
  std::ifstream in(path);
  std::string line;
  while (rows.size() < limit && std::getline(in, line)) {
    std::size_t p = 0;
    for (int i = 0; i < 4; ++i) p = line.find('\t', p) + 1;
    rows.push_back({std::stoll(line.substr(0, line.find('\t'))), line.substr(p)});
  }
  return rows;
}

constexpr std::size_t kCandidates = 25;

// A navigable small-world graph in layers (Malkov & Yashunin), over sketches, with the
// distance counted.
struct Hnsw {
  const std::vector<arg::ShapeSketch>& s;
  std::size_t m, ef_construction;
  std::vector<std::vector<std::vector<std::uint32_t>>> links;  // [node][layer]
  std::uint32_t entry = 0;
  int top = -1;
  std::size_t distances = 0;

  double d(std::size_t a, const arg::ShapeSketch& q) {
    ++distances;
    return arg::sketch_distance(q, s[a]);
  }
  using Hit = std::pair<double, std::uint32_t>;
  // The ef nearest found from `from` on `layer`, nearest first.
  std::vector<Hit> search_layer(const arg::ShapeSketch& q, std::vector<Hit> from, std::size_t ef,
                                int layer) {
    std::set<std::uint32_t> seen;
    std::priority_queue<Hit, std::vector<Hit>, std::greater<Hit>> next;
    std::priority_queue<Hit> best;
    for (const Hit& h : from) seen.insert(h.second), next.push(h), best.push(h);
    while (!next.empty()) {
      const Hit c = next.top();
      next.pop();
      if (best.size() >= ef && c.first > best.top().first) break;
      for (std::uint32_t n : links[c.second][std::size_t(layer)]) {
        if (!seen.insert(n).second) continue;
        const double dn = d(n, q);
        if (best.size() < ef || dn < best.top().first) {
          next.push({dn, n});
          best.push({dn, n});
          if (best.size() > ef) best.pop();
        }
      }
    }
    std::vector<Hit> out;
    for (; !best.empty(); best.pop()) out.push_back(best.top());
    std::reverse(out.begin(), out.end());
    return out;
  }
  std::vector<Hit> search(const arg::ShapeSketch& q, std::size_t ef) {
    std::vector<Hit> at = {{d(entry, q), entry}};
    for (int layer = top; layer > 0; --layer) at = {search_layer(q, at, 1, layer)[0]};
    return search_layer(q, at, ef, 0);
  }
  void insert(std::uint32_t node, int level) {
    links[node].resize(std::size_t(level) + 1);
    if (top < 0) {
      entry = node, top = level;
      return;
    }
    std::vector<Hit> at = {{d(entry, s[node]), entry}};
    for (int layer = top; layer > level; --layer) at = {search_layer(s[node], at, 1, layer)[0]};
    for (int layer = std::min(level, top); layer >= 0; --layer) {
      at = search_layer(s[node], at, ef_construction, layer);
      const std::size_t keep = layer == 0 ? 2 * m : m;
      for (std::size_t k = 0; k < std::min(m, at.size()); ++k) {
        const std::uint32_t n = at[k].second;
        links[node][std::size_t(layer)].push_back(n);
        auto& back = links[n][std::size_t(layer)];
        back.push_back(node);
        if (back.size() > keep) {  // keep the nearest
          std::vector<Hit> by;
          for (std::uint32_t b : back) by.push_back({d(b, s[n]), b});
          std::sort(by.begin(), by.end());
          back.clear();
          for (std::size_t i = 0; i < keep; ++i) back.push_back(by[i].second);
        }
      }
    }
    if (level > top) entry = node, top = level;
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: hnsw_study ROWS.copy N QUERIES.copy [POOL]\n";
    return 2;
  }
  const std::size_t limit = std::stoul(argv[2]);
  const long long pool = argc > 4 ? std::stoll(argv[4]) : 0;
  const std::vector<Row> queries = read_rows(argv[3], 100000);
  std::set<long long> query_ids;
  for (const Row& q : queries) query_ids.insert(q.id);
  std::vector<Row> rows;
  for (Row& r : read_rows(argv[1], limit))
    if (pool == 0 || !query_ids.count((r.id - 1) % pool + 1)) rows.push_back(std::move(r));
  const std::size_t n = rows.size(), nq = queries.size();
  const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<arg::ShapeSketch> sketch(n), qsketch(nq);
  std::vector<arg::ArgGraph> qgraph(nq);
  for (std::size_t i = 0; i < nq; ++i) {
    qgraph[i] = arg::deserialize_arg(arg::arg_from_text(queries[i].text));
    qsketch[i] = arg::shape_sketch(qgraph[i]);
  }
  std::vector<float> sim(nq * n);
  arg::parallel_for(n, threads, [&](std::size_t j) {
    const arg::ArgGraph g = arg::deserialize_arg(arg::arg_from_text(rows[j].text));
    sketch[j] = arg::shape_sketch(g);
    for (std::size_t i = 0; i < nq; ++i) sim[i * n + j] = float(arg::arg_similarity(g, qgraph[i]));
  });
  std::vector<std::vector<std::size_t>> top10(nq);
  for (std::size_t i = 0; i < nq; ++i) {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    const float* row = &sim[i * n];
    std::partial_sort(order.begin(), order.begin() + 10, order.end(),
                      [&](auto a, auto b) { return row[a] != row[b] ? row[a] < row[b] : a < b; });
    top10[i].assign(order.begin(), order.begin() + 10);
  }
  auto recall = [&](std::size_t i, std::vector<std::size_t> got) {
    std::sort(got.begin(), got.end());
    double r = 0;
    for (std::size_t x : top10[i]) r += std::binary_search(got.begin(), got.end(), x) ? 0.1 : 0;
    return r;
  };

  // What a coarse distance costs against a sketch distance, here.
  double coarse_cost = 0.1;
  {
    const std::string bytes = arg::write_shape_sketch(sketch[0]);
    const arg::CoarseQuery cq = arg::coarse_query(qsketch[0]);
    volatile double sink = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < 20000; ++k) sink = sink + arg::sketch_distance(qsketch[0], sketch[0]);
    const auto t1 = std::chrono::steady_clock::now();
    for (int k = 0; k < 20000; ++k) sink = sink + arg::coarse_sketch_distance(cq, bytes);
    const auto t2 = std::chrono::steady_clock::now();
    coarse_cost = std::chrono::duration<double>(t2 - t1).count() /
                  std::chrono::duration<double>(t1 - t0).count();
    std::printf(
        "%zu rows, %zu queries%s; a coarse distance costs %.3f of a sketch distance (%.2f us)\n", n,
        nq, pool ? " (held out)" : "", coarse_cost,
        std::chrono::duration<double, std::micro>(t1 - t0).count() / 20000);
  }
  std::printf("%-6s %-14s %12s %12s %12s %10s\n", "index", "setting", "sketch d.", "coarse d.",
              "equivalent", "recall@10");

  // Every row by the sketch distance: what either index can at best hand to SIM.
  {
    double r = 0;
    for (std::size_t i = 0; i < nq; ++i) {
      std::vector<std::pair<double, std::size_t>> all(n);
      for (std::size_t j = 0; j < n; ++j) all[j] = {arg::sketch_distance(qsketch[i], sketch[j]), j};
      std::partial_sort(all.begin(), all.begin() + std::ptrdiff_t(kCandidates), all.end());
      std::vector<std::size_t> got;
      for (std::size_t k = 0; k < kCandidates; ++k) got.push_back(all[k].second);
      r += recall(i, got);
    }
    std::printf("%-6s %-14s %12zu %12d %12zu %10.3f\n", "every", "row", n, 0, n, r / nq);
  }

  // The inverted file as the index searches it: centres, probed cells' rows by the coarse
  // distance, the 4 x 25 nearest by the sketch distance, the 25 nearest of those to SIM.
  const std::size_t cells = std::size_t(std::ceil(std::sqrt(double(n))));
  const std::vector<arg::ShapeSketch> centres = study::sampled_centres(sketch, cells);
  const std::vector<arg::CoarseQuery> coarse = arg::coarse_centres(centres.data(), centres.size());
  std::vector<std::size_t> cell(n);
  arg::parallel_for(n, threads, [&](std::size_t j) {
    cell[j] = arg::nearest_cell(sketch[j], centres.data(), centres.size(), coarse.data());
  });
  std::vector<std::string> bytes(n);
  for (std::size_t j = 0; j < n; ++j) bytes[j] = arg::write_shape_sketch(sketch[j]);
  for (std::size_t probes : {1, 2, 4, 8, 16}) {
    double exact = 0, rough = 0, r = 0;
    for (std::size_t i = 0; i < nq; ++i) {
      std::vector<char> probed(centres.size(), 0);
      for (std::size_t c :
           arg::cells_to_probe(qsketch[i], centres.data(), centres.size(), probes, coarse.data()))
        probed[c] = 1;
      rough += double(centres.size());
      exact += double(std::min(centres.size(), arg::kCellsRefined));
      const arg::CoarseQuery cq = arg::coarse_query(qsketch[i]);
      std::vector<std::pair<double, std::size_t>> read;
      for (std::size_t j = 0; j < n; ++j)
        if (probed[cell[j]]) read.push_back({arg::coarse_sketch_distance(cq, bytes[j]), j});
      rough += double(read.size());
      const std::size_t whole = std::min(read.size(), 4 * kCandidates);
      std::partial_sort(read.begin(), read.begin() + std::ptrdiff_t(whole), read.end());
      std::vector<std::pair<double, std::size_t>> refined;
      for (std::size_t k = 0; k < whole; ++k)
        refined.push_back(
            {arg::sketch_distance(qsketch[i], sketch[read[k].second]), read[k].second});
      exact += double(whole);
      std::sort(refined.begin(), refined.end());
      std::vector<std::size_t> got;
      for (std::size_t k = 0; k < std::min(kCandidates, refined.size()); ++k)
        got.push_back(refined[k].second);
      r += recall(i, got);
    }
    std::printf("%-6s probes %-7zu %12.0f %12.0f %12.0f %10.3f\n", "ivf", probes, exact / nq,
                rough / nq, (exact + coarse_cost * rough) / nq, r / nq);
    std::fflush(stdout);
  }

  // The graph: M = 16, ef_construction = 64 (pgvector's defaults), levels at random.
  Hnsw h{sketch, 16, 64, {}, 0, -1, 0};
  h.links.resize(n);
  const auto t0 = std::chrono::steady_clock::now();
  arg::SeededRandom levels(7);
  for (std::size_t j = 0; j < n; ++j) {
    const int level = int(-std::log(std::max(1e-12, levels.unit())) / std::log(16.0));
    h.insert(std::uint32_t(j), level);
  }
  std::printf("hnsw built: %.0f sketch distances a row, %.0f s on one thread\n",
              double(h.distances) / double(n),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  for (std::size_t ef : {25, 40, 80, 160, 320}) {
    h.distances = 0;
    double r = 0;
    for (std::size_t i = 0; i < nq; ++i) {
      std::vector<std::size_t> got;
      for (const auto& hit : h.search(qsketch[i], ef))
        if (got.size() < kCandidates) got.push_back(hit.second);
      r += recall(i, got);
    }
    std::printf("%-6s ef %-11zu %12.0f %12.0f %12.0f %10.3f\n", "hnsw", ef,
                double(h.distances) / nq, 0.0, double(h.distances) / nq, r / nq);
    std::fflush(stdout);
  }
  return 0;
}
