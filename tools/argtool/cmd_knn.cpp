// argtool knn: brute-force ground truth for the index benchmarks, outside the database.
//
// Ranks every row of a scale-gen COPY stream by SIM against each query row and writes each
// query's K nearest, ties by id, as `ORDER BY descr <~> q, id LIMIT K` over the table would
// (the same core SIM, default weights, the row first as in `descr <~> q`). Rows stream in
// batches, so a million rows (about 23 GB of text) need never be on disk: scale-gen writes
// them to a pipe. In SQL the same truth costs one parallel scan per query, about an hour for
// 100 queries over a million rows; here one pass reads each row once for every query.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_set>
#include <utility>
#include <vector>

#include "command_registry.hpp"
#include "common/parallel_for.hpp"
#include "graph/serialize.hpp"
#include "match/match_prep.hpp"
#include "match/similarity.hpp"

namespace {

struct KnnArgs {
  std::string rows = "-", queries, out = "-";
  std::vector<std::string> filters;  // NAME=M1,M2,...
  int k = 10;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
};

// A row of scale-gen's COPY text: its id, museum and value.
struct Row {
  long long id = 0;
  std::string museum;
  arg::ArgGraph graph;
};

Row parse_row(const std::string& line, const std::string& where) {
  std::size_t tab[4], at = 0;
  for (std::size_t& t : tab) {
    t = line.find('\t', at);
    if (t == std::string::npos) throw std::runtime_error(where + ": not a scale-gen row");
    at = t + 1;
  }
  Row row;
  std::size_t used = 0;
  row.id = std::stoll(line.substr(0, tab[0]), &used);
  if (used != tab[0]) throw std::runtime_error(where + ": the id is not a number");
  row.museum = line.substr(tab[0] + 1, tab[1] - tab[0] - 1);
  row.graph = arg::deserialize_arg(arg::arg_from_text(line.substr(tab[3] + 1)));
  return row;
}

// A filter: which museums' rows it keeps ("none" keeps every row).
struct Filter {
  std::string name;
  std::unordered_set<std::string> museums;
  bool keeps(const std::string& museum) const { return museums.empty() || museums.count(museum); }
};

Filter parse_filter(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw std::runtime_error("--filter wants NAME=MUSEUM,MUSEUM,...: " + text);
  Filter f{text.substr(0, eq), {}};
  std::size_t at = eq + 1;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    if (comma == at) throw std::runtime_error("--filter has an empty museum: " + text);
    f.museums.insert(text.substr(at, comma - at));
    at = comma + 1;
  }
  return f;
}

// The K best (sim, id) pairs seen, as a max-heap on (sim, id): the worst kept is on top.
struct TopK {
  std::vector<std::pair<double, long long>> heap;
  void offer(double sim, long long id, int k) {
    const std::pair<double, long long> e{sim, id};
    if (int(heap.size()) < k) {
      heap.push_back(e);
      std::push_heap(heap.begin(), heap.end());
    } else if (e < heap.front()) {
      std::pop_heap(heap.begin(), heap.end());
      heap.back() = e;
      std::push_heap(heap.begin(), heap.end());
    }
  }
};

int run(const KnnArgs& a) {
  std::vector<Filter> filters{{"none", {}}};
  for (const std::string& f : a.filters) filters.push_back(parse_filter(f));

  std::vector<Row> queries;
  {
    std::ifstream in(a.queries, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + a.queries);
    std::string line;
    while (std::getline(in, line)) queries.push_back(parse_row(line, a.queries));
  }
  if (queries.empty()) throw std::runtime_error(a.queries + " has no rows");
  std::vector<arg::MatchPrep> preps(queries.size());
  for (std::size_t q = 0; q < queries.size(); ++q)
    arg::prepare_match(queries[q].graph, arg::Weights{}, preps[q]);

  std::ifstream file;
  if (a.rows != "-") {
    file.open(a.rows, std::ios::binary);
    if (!file) throw std::runtime_error("cannot read " + a.rows);
  }
  std::istream& in = a.rows == "-" ? std::cin : file;

  std::vector<std::vector<TopK>> best(filters.size(), std::vector<TopK>(queries.size()));
  const std::size_t batch = 1024;
  std::vector<std::string> lines;
  std::vector<Row> rows(batch);
  std::vector<double> sims(batch * queries.size());
  long long seen = 0;
  for (bool more = true; more;) {
    lines.clear();
    std::string line;
    while (lines.size() < batch && (more = bool(std::getline(in, line))))
      lines.push_back(std::move(line));
    const std::size_t n = lines.size();
    arg::parallel_for(n, a.threads, [&](std::size_t i) {
      rows[i] = parse_row(lines[i], "row " + std::to_string(seen + (long long)i + 1));
      for (std::size_t q = 0; q < queries.size(); ++q)
        sims[i * queries.size() + q] = arg::arg_similarity(
            rows[i].graph, queries[q].graph, arg::Weights{}, nullptr, nullptr, &preps[q]);
    });
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t f = 0; f < filters.size(); ++f)
        if (filters[f].keeps(rows[i].museum))
          for (std::size_t q = 0; q < queries.size(); ++q)
            best[f][q].offer(sims[i * queries.size() + q], rows[i].id, a.k);
    seen += (long long)n;
    if (seen % (batch * 64) == 0 && n == batch) std::fprintf(stderr, "knn: %lld rows\n", seen);
  }

  std::ofstream out_file;
  if (a.out != "-") {
    out_file.open(a.out, std::ios::binary);
    if (!out_file) throw std::runtime_error("cannot write " + a.out);
  }
  std::ostream& out = a.out == "-" ? std::cout : out_file;
  // COPY text rows: filter, query id, the ids nearest first.
  for (std::size_t f = 0; f < filters.size(); ++f)
    for (std::size_t q = 0; q < queries.size(); ++q) {
      std::vector<std::pair<double, long long>> ranked = best[f][q].heap;
      std::sort(ranked.begin(), ranked.end());
      out << filters[f].name << '\t' << queries[q].id << "\t{";
      for (std::size_t r = 0; r < ranked.size(); ++r) out << (r ? "," : "") << ranked[r].second;
      out << "}\n";
    }
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + a.out);
  std::fprintf(stderr, "knn: %lld rows, %zu queries, %zu filters\n", seen, queries.size(),
               filters.size());
  return 0;
}

const bool registered = argtool::register_command(
    "knn",
    "brute-force K nearest by SIM of scale-gen rows (a file or a stream) to query rows, as COPY "
    "rows: filter, query id, ids",
    [](CLI::App& app) {
      auto a = std::make_shared<KnnArgs>();
      app.add_option("--rows", a->rows, "scale-gen COPY rows to rank (- for stdin)");
      app.add_option("--queries", a->queries, "scale-gen COPY rows, the queries")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("--out", a->out, "file to write the truth rows to (- for stdout)");
      app.add_option("--k", a->k, "nearest rows kept a query")->check(CLI::Range(1, 10000));
      app.add_option("--filter", a->filters,
                     "NAME=M1,M2,...: also the nearest among those museums' rows (repeatable)");
      app.add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 256));
      return [a] { return run(*a); };
    });

}  // namespace
