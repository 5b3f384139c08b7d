// How much of SIM's ten nearest an arg_ivf search finds: the cells of search/sketch_cells.hpp
// (centres from a sample of 20 a cell, as the index's build takes them), the probed cells' rows
// ranked by sketch distance, and the recall of SIM's ten nearest among the first S of them, for
// cell counts around the default (the square root of the rows) and probe counts; with the
// mean rows a search reads. Reads the COPY rows of `argtool scale-gen` like descriptor_study.
// Exits 0 either way: a study, not a test.
//
//   tests/scale/descriptor_study.sh --ivf SET [QUERIES]   (SET: a .copy or labels.csv)
//
// Every model is a query when there are at most 2,000; otherwise QUERIES models spread over the
// file (default 40).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include "common/parallel_for.hpp"
#include "common/random.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "sampled_centres.hpp"
#include "search/sketch_cells.hpp"

namespace {

std::string arg_text(const std::string& line) {
  std::size_t p = 0;
  for (int i = 0; i < 4; ++i) p = line.find('\t', p) + 1;
  return line.substr(p);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: ivf_study FILE.copy [QUERIES]\n";
    return 2;
  }
  const std::size_t max_queries = argc > 2 ? std::stoul(argv[2]) : 40;
  std::vector<std::string> texts;
  {
    std::ifstream in(argv[1]);
    std::string line;
    while (std::getline(in, line)) texts.push_back(arg_text(line));
  }
  const std::size_t n = texts.size();
  const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<arg::ShapeSketch> sketch(n);
  arg::parallel_for(n, threads, [&](std::size_t j) {
    sketch[j] = arg::shape_sketch(arg::deserialize_arg(arg::arg_from_text(texts[j])));
  });
  std::vector<std::size_t> qs;
  for (std::size_t i = 0, m = n <= 2000 ? n : max_queries; i < m; ++i) qs.push_back(i * n / m);
  const std::size_t nq = qs.size();
  std::fprintf(stderr, "%zu models, %zu queries; SIM of each query with every model...\n", n, nq);
  // SIM's ten nearest of each query, and every model's sketch distance to it.
  std::vector<std::vector<std::size_t>> top10(nq);
  std::vector<float> by_sketch(nq * n);
  {
    std::vector<arg::ArgGraph> query(nq);
    for (std::size_t i = 0; i < nq; ++i)
      query[i] = arg::deserialize_arg(arg::arg_from_text(texts[qs[i]]));
    std::vector<float> sim(nq * n, 2.0f);
    arg::parallel_for(n, threads, [&](std::size_t j) {
      const arg::ArgGraph g = arg::deserialize_arg(arg::arg_from_text(texts[j]));
      for (std::size_t i = 0; i < nq; ++i) {
        by_sketch[i * n + j] = float(arg::sketch_distance(sketch[qs[i]], sketch[j]));
        if (qs[i] != j) sim[i * n + j] = float(arg::arg_similarity(query[i], g));
      }
    });
    for (std::size_t i = 0; i < nq; ++i) {
      std::vector<std::size_t> order(n);
      std::iota(order.begin(), order.end(), 0);
      const float* row = &sim[i * n];
      std::partial_sort(order.begin(), order.begin() + 10, order.end(),
                        [&](auto a, auto b) { return row[a] != row[b] ? row[a] < row[b] : a < b; });
      top10[i].assign(order.begin(), order.begin() + 10);
    }
  }
  const std::size_t root = std::size_t(std::ceil(std::sqrt(double(n))));
  const std::size_t shortlists[] = {50, 100, 200};
  std::printf(
      "cells  probes  rows read   recall@10 among the first S = 50 / 100 / 200 (%zu queries)\n",
      nq);
  for (std::size_t cells : {root / 2, root, 2 * root}) {
    const std::vector<arg::ShapeSketch> centres = study::sampled_centres(sketch, cells);
    std::vector<std::size_t> cell(n);
    arg::parallel_for(n, threads, [&](std::size_t j) {
      cell[j] = arg::nearest_cell(sketch[j], centres.data(), centres.size());
    });
    for (std::size_t probes : {4, 8, 12, 16, 32}) {
      double read = 0, recall[3] = {0, 0, 0};
      for (std::size_t i = 0; i < nq; ++i) {
        std::vector<char> probed(centres.size(), 0);
        for (std::size_t c :
             arg::cells_to_probe(sketch[qs[i]], centres.data(), centres.size(), probes))
          probed[c] = 1;
        std::vector<std::pair<float, std::size_t>> rows;
        for (std::size_t j = 0; j < n; ++j)
          if (j != qs[i] && probed[cell[j]]) rows.push_back({by_sketch[i * n + j], j});
        read += double(rows.size());
        std::sort(rows.begin(), rows.end());
        for (int s = 0; s < 3; ++s) {
          std::vector<std::size_t> first;
          for (std::size_t k = 0; k < std::min(shortlists[s], rows.size()); ++k)
            first.push_back(rows[k].second);
          std::sort(first.begin(), first.end());
          for (std::size_t x : top10[i])
            recall[s] += std::binary_search(first.begin(), first.end(), x) ? 0.1 : 0.0;
        }
      }
      std::printf("%5zu  %6zu  %9.0f   %.3f / %.3f / %.3f\n", centres.size(), probes, read / nq,
                  recall[0] / nq, recall[1] / nq, recall[2] / nq);
      std::fflush(stdout);
    }
  }
  return 0;
}
