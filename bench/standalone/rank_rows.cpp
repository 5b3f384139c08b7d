// A brute-force ranking in process, as arg_sim runs it on every row of ORDER BY <~>: each query
// decoded and prepared once, each row read from its stored bytes into the matcher's keys (or
// decoded whole when it cannot be), then SIM. Prints the median time a row over the rounds;
// with a dump file, writes every SIM (queries x rows doubles) so two builds can be compared
// byte for byte with cmp. Built and run by bench/rank_rows.sh (bench/standalone is outside the
// CMake glob of bench/*.cpp: this program has its own main).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "graph/comparable.hpp"
#include "graph/serialize.hpp"
#include "match/match_prep.hpp"
#include "match/packed_graph.hpp"
#include "match/similarity.hpp"

namespace {

// SIM of a prepared query and a row's stored bytes, by the path the extension takes. Not inlined,
// so that a profiler can count a row's work alone (valgrind --toggle-collect='*row_sim*').
[[gnu::noinline]] double row_sim(const arg::ArgGraph& query, const arg::MatchPrep& prep,
                                 const std::string& row, arg::PackedGraph& packed) {
  const arg::Weights weights;
  double sim = 0;
  if (arg::read_packed_graph(row, weights, packed)) {
    arg::require_comparable(query, packed.head);
    if (arg::packed_similarity(query, &prep, packed, weights, sim)) return sim;
  }
  const arg::ArgGraph g = arg::deserialize_arg(row, /*check_digest=*/false);
  arg::require_comparable(query, g);
  return arg::arg_similarity(query, g, weights, nullptr, &prep, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: rank_rows COPY_FILE [QUERIES [ROUNDS [DUMP]]]\n";
    return 2;
  }
  // COPY rows of `argtool scale-gen`: the arg's text form is the last field.
  std::ifstream in(argv[1]);
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);)
    rows.push_back(arg::arg_from_text(line.substr(line.rfind('\t') + 1)));
  if (rows.empty()) {
    std::cerr << "rank_rows: no rows in " << argv[1] << "\n";
    return 1;
  }
  const std::size_t queries = std::min<std::size_t>(rows.size(), argc > 2 ? std::atoi(argv[2]) : 1);
  const int rounds = std::max(1, argc > 3 ? std::atoi(argv[3]) : 21);
  std::vector<arg::ArgGraph> query(queries);
  std::vector<arg::MatchPrep> prep(queries);
  for (std::size_t q = 0; q < queries; ++q) {
    query[q] = arg::deserialize_arg(rows[q]);
    arg::prepare_match(query[q], arg::Weights{}, prep[q]);
  }
  arg::PackedGraph packed;
  std::vector<double> sims(queries * rows.size()), per_row;
  for (int round = 0; round < rounds; ++round) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t q = 0; q < queries; ++q)
      for (std::size_t r = 0; r < rows.size(); ++r)
        sims[q * rows.size() + r] = row_sim(query[q], prep[q], rows[r], packed);
    const auto end = std::chrono::steady_clock::now();
    per_row.push_back(std::chrono::duration<double, std::micro>(end - start).count() /
                      double(sims.size()));
  }
  std::sort(per_row.begin(), per_row.end());
  std::printf("%zu queries x %zu rows, %d rounds: median %.2f us a row (fastest %.2f)\n", queries,
              rows.size(), rounds, per_row[per_row.size() / 2], per_row.front());
  if (argc > 4) {
    std::ofstream dump(argv[4], std::ios::binary);
    dump.write(reinterpret_cast<const char*>(sims.data()), std::streamsize(8 * sims.size()));
  }
}
