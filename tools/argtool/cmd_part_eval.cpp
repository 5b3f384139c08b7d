// argtool part-eval: parts cut from labelled models query the set; part matching against SIM.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

#include "command_registry.hpp"
#include "common/random.hpp"
#include "eval/label_file.hpp"
#include "eval/retrieval_metrics.hpp"
#include "eval_models.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "load_arg.hpp"
#include "match/similarity.hpp"
#include "match/subgraph.hpp"
#include "pipeline/build_arg.hpp"
#include "pipeline/node_positions.hpp"
#include "pipeline/node_region.hpp"
#include "progress_bar.hpp"

namespace fs = std::filesystem;

namespace {

struct PartEvalArgs {
  std::vector<std::string> labels, presets = {"part", "mrg"};
  std::vector<int> query_levels = {0};
  std::string cache, json, parts;
  int level = 2, per_class = 0, min_faces = 200;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  std::uint64_t seed = 1;
  double threshold = 0.5;
  bool in_situ = true;
  arg::BuildOptions options;
};

using argtool::Model;

// One part query: node `node` of `level` of model `source`, cut out and built on its own.
struct PartQuery {
  std::size_t source = 0;
  int node = 0;
  long faces = 0;   // triangles of the cut
  double area = 0;  // the node's area share in the source's ARG, of its level
  arg::ArgGraph part;
  std::string error;  // why the model gave no query
};

int level_size(const arg::ArgGraph& g, int level) {
  return int(g.level_begin[std::size_t(level) + 1] - g.level_begin[std::size_t(level)]);
}

// The nodes of `level` that can stand for a part: attached to the rest by one neighbour (a
// limb, a handle, a head) and not the level's largest node (the body), largest first, index
// breaking ties, so the choice is fixed by the ARG.
std::vector<int> part_nodes(const arg::ArgGraph& g, int level) {
  const std::uint32_t begin = g.level_begin[std::size_t(level)];
  const int count = level_size(g, level);
  int largest = 0;
  for (int k = 1; k < count; ++k)
    if (g.nodes[begin + std::uint32_t(k)].a > g.nodes[begin + std::uint32_t(largest)].a)
      largest = k;
  std::vector<int> out;
  for (int k = 0; k < count; ++k)
    if (k != largest && g.nodes[begin + std::uint32_t(k)].adj_count == 1) out.push_back(k);
  std::stable_sort(out.begin(), out.end(), [&](int x, int y) {
    return g.nodes[begin + std::uint32_t(x)].a > g.nodes[begin + std::uint32_t(y)].a;
  });
  return out;
}

// Cuts the first part node of `model` whose region has at least min_faces triangles and builds
// its ARG with the run's options; writes the cut into `parts_dir` when given. Never throws:
// failures land in PartQuery::error.
PartQuery make_query(std::size_t source, const std::string& path, const Model& model,
                     const PartEvalArgs& a, const std::string& parts_dir) {
  PartQuery q;
  q.source = source;
  try {
    if (!model.error.empty()) throw std::runtime_error("model failed: " + model.error);
    if (a.level > model.graph.levels())
      throw std::runtime_error("no level " + std::to_string(a.level));
    const std::vector<int> nodes = part_nodes(model.graph, a.level);
    if (nodes.empty()) throw std::runtime_error("no node with one neighbour at the level");
    // The surface the ARG was built on, with each triangle's node (node k here is node k of
    // the ARG's level).
    const arg::NodePositions p =
        arg::node_positions(arg::read_mesh(argtool::read_file_bytes(path)), a.options);
    if (int(p.levels[std::size_t(a.level)].area.size()) != level_size(model.graph, a.level))
      throw std::runtime_error("node positions do not match the ARG's level");
    for (int node : nodes) {
      // A node may own no triangle's middle (a thin band): the next one then.
      long faces = 0;
      for (int f = 0; f < int(p.mesh.F.rows()); ++f) faces += arg::face_node(p, a.level, f) == node;
      if (faces < a.min_faces) continue;
      q.node = node;
      q.faces = faces;
      q.area =
          model.graph.nodes[model.graph.level_begin[std::size_t(a.level)] + std::uint32_t(node)].a *
          (model.graph.levels() + 1);
      const arg::Mesh region = arg::node_region(p, a.level, node);
      q.part = arg::build_arg(region, a.options);
      if (!parts_dir.empty())
        argtool::write_file_bytes(
            (fs::path(parts_dir) / (fs::path(path).stem().string() + ".off")).string(),
            arg::write_off(region));
      return q;
    }
    throw std::runtime_error("no part node of " + std::to_string(a.min_faces) +
                             " triangles or more");
  } catch (const std::exception& e) {
    q.error = e.what();
  }
  return q;
}

// The models that give queries: every model, or the first `per_class` of each class in a
// seeded shuffle of the class (the same models for the same seed), in label order.
std::vector<std::size_t> sampled_models(const arg::LabelSet& set, int per_class,
                                        std::uint64_t seed) {
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < set.classes.size(); ++c) {
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < set.models.size(); ++i)
      if (set.class_of[i] == int(c)) members.push_back(i);
    arg::SeededRandom random(seed * 1000003u + c);
    for (std::size_t i = members.size(); i > 1; --i)  // Fisher-Yates
      std::swap(members[i - 1], members[std::size_t(random.below(int(i)))]);
    if (per_class > 0 && members.size() > std::size_t(per_class)) members.resize(per_class);
    out.insert(out.end(), members.begin(), members.end());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// How a method scores a candidate model for a query.
enum class Score {
  whole,     // SIM(query, candidate): the query as a whole shape
  part,      // part_match's best (lowest) score; no match ranks after every match
  subgraph,  // the best SIM(query, sub-graph below a candidate node) at the cut's level +-1
};

// One ranking method over the queries: how far each candidate model is from each query.
struct Method {
  std::string name, query;  // query: what the query is ("cut part, level 0", ...)
  bool in_situ = false;     // the query is the node in its source model; the source left out
  int query_level = 0;      // part methods: the level of the query node
  Score score = Score::whole;
  arg::Weights weights;
  std::vector<double> distance;  // queries x models
  std::vector<char> matched;     // part methods: the candidate had a match
};

// The score of a candidate part_match finds nothing in: worse than any match (scores are in
// [0, 1]); such candidates are ordered among themselves by a seeded shuffle, not by label
// order, which would favour the classes listed first.
double no_match(std::size_t query, std::size_t model, std::size_t models, std::uint64_t seed) {
  arg::SeededRandom random(seed ^ (0x9e3779b97f4a7c15ull * (query + 1)) ^ (model << 20));
  return 1.0 + (1.0 + random.unit() * double(models)) / double(models + 1);
}

// The largest node of `level` of the part's own ARG, the query node of a cut part (at level 0
// the part itself when it is in one piece).
int largest_node(const arg::ArgGraph& g, int level) {
  const std::uint32_t begin = g.level_begin[std::size_t(level)];
  int best = 0;
  for (int k = 1; k < level_size(g, level); ++k)
    if (g.nodes[begin + std::uint32_t(k)].a > g.nodes[begin + std::uint32_t(best)].a) best = k;
  return best;
}

std::vector<Method> methods_of(const PartEvalArgs& a) {
  const arg::Weights standard = arg::parse_weights("arg");
  std::vector<Method> out;
  out.push_back({"SIM", "cut part as a whole", false, 0, Score::whole, standard, {}, {}});
  for (int q : a.query_levels)
    for (const auto& preset : a.presets)
      out.push_back({"part " + preset,
                     "cut part, level " + std::to_string(q),
                     false,
                     q,
                     Score::part,
                     arg::parse_weights(preset),
                     {},
                     {}});
  out.push_back(
      {"SIM sub-graph", "cut part as a whole", false, a.level, Score::subgraph, standard, {}, {}});
  if (a.in_situ) {
    for (const auto& preset : a.presets)
      out.push_back({"part " + preset,
                     "node in its model",
                     true,
                     a.level,
                     Score::part,
                     arg::parse_weights(preset),
                     {},
                     {}});
    out.push_back({"SIM", "its whole model", true, 0, Score::whole, standard, {}, {}});
  }
  return out;
}

// The best SIM of `part` against the sub-graphs below the nodes of `candidate` at levels
// level - 1 .. level + 1: where the cut part's own graph meets the candidate's nodes at the
// depth it was cut from, which part_match (query level and candidate level tied) cannot do
// for a query node at level 0.
double best_subgraph_sim(const arg::ArgGraph& part, const arg::ArgGraph& candidate, int level,
                         const arg::Weights& w) {
  double best = 1.0;
  for (int r = std::max(0, level - 1); r <= std::min(candidate.levels(), level + 1); ++r)
    for (std::uint32_t i = candidate.level_begin[std::size_t(r)];
         i < candidate.level_begin[std::size_t(r) + 1]; ++i)
      best = std::min(best, arg::arg_similarity(part, arg::subgraph(candidate, int(i)), w));
  return best;
}

// Fills one query's row of every method.
void rank_query(std::size_t qi, const PartQuery& q, const std::vector<Model>& models,
                std::vector<Method>& methods, const PartEvalArgs& a) {
  const std::size_t n = models.size();
  const arg::ArgGraph& source = models[q.source].graph;
  for (Method& m : methods) {
    double* row = m.distance.data() + qi * n;
    char* hit = m.matched.data() + qi * n;
    const arg::ArgGraph& query = m.in_situ ? source : q.part;
    const int level = m.in_situ ? a.level : std::min(m.query_level, q.part.levels());
    const int node = m.in_situ ? q.node : largest_node(q.part, level);
    for (std::size_t j = 0; j < n; ++j) {
      if (!models[j].error.empty() || (m.in_situ && j == q.source)) continue;
      const arg::ArgGraph& candidate = models[j].graph;
      if (m.score == Score::whole) {
        row[j] = arg::arg_similarity(query, candidate, m.weights);
      } else if (m.score == Score::subgraph) {
        row[j] = best_subgraph_sim(query, candidate, m.query_level, m.weights);
      } else {
        const auto parts = arg::part_match(query, level, node, candidate, m.weights, a.threshold);
        hit[j] = !parts.empty();
        row[j] = parts.empty() ? no_match(qi, j, n, a.seed) : parts.front().score;
      }
    }
  }
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

const bool registered = argtool::register_command(
    "part-eval",
    "part retrieval on labelled sets: a part cut from a model at a node queries the set (its "
    "model and class relevant); part matching against SIM, NN / FT / mAP",
    [](CLI::App& app) {
      auto a = std::make_shared<PartEvalArgs>();
      app.add_option("--labels", a->labels, "CSV with header model_id,path,class (repeatable)")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("--level", a->level,
                     "level of the node cut out: among the nodes with one neighbour that are not "
                     "the level's largest, the largest of at least --min-faces triangles")
          ->check(CLI::Range(0, 16));
      app.add_option("--min-faces", a->min_faces, "fewest triangles a cut part may have")
          ->check(CLI::Range(1, 1 << 30));
      app.add_option("--per-class", a->per_class,
                     "models per class that give a query, a seeded sample (0: every model)")
          ->check(CLI::Range(0, 1 << 20));
      app.add_option("--seed", a->seed, "seed of the sample and of the order of non-matches");
      app.add_option("--preset", a->presets,
                     "weights presets of part matching (repeatable; default part and mrg)");
      app.add_option("--query-level", a->query_levels,
                     "level of the cut part's own ARG whose largest node is the query "
                     "(repeatable; default 0, the whole part)")
          ->check(CLI::Range(0, 16));
      app.add_option("--threshold", a->threshold,
                     "node similarity a candidate part needs (part matching's, default 0.5)")
          ->check(CLI::Range(0.0, 1.0));
      app.add_flag("!--no-in-situ", a->in_situ,
                   "leave out the rows where the query is the node in its own model");
      app.add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 256));
      app.add_option("--cache", a->cache, "folder caching built ARGs between runs");
      app.add_option("--json", a->json, "write the scores as JSON");
      app.add_option("--parts", a->parts,
                     "write each cut part as DIR/SET/MODEL.off, to look at what was queried");
      argtool::add_build_flags(app, a->options, false);
      return [a] {
        for (const auto& p : a->presets) arg::parse_weights(p);  // a bad name fails first
        if (!a->cache.empty()) fs::create_directories(a->cache);
        std::vector<std::string> table;
        nlohmann::json out = nlohmann::json::array();
        char line[256];
        std::snprintf(line, sizeof line, "%-10s %-26s %-11s %7s %6s %6s %6s %7s %7s %7s %7s", "set",
                      "query", "method", "queries", "NN", "FT", "mAP", "matched", "src_hit",
                      "src@1", "seconds");
        table.push_back(line);
        for (const std::string& labels : a->labels) {
          const std::string name = argtool::set_name(labels);
          const arg::LabelSet set = arg::parse_label_csv(argtool::read_file_bytes(labels));
          const fs::path root = fs::path(labels).parent_path();
          auto t0 = std::chrono::steady_clock::now();
          std::vector<Model> models(set.models.size());
          argtool::run_with_progress(
              "build " + name, models.size(), a->threads, [&](std::size_t i) {
                argtool::prepare_model(models[i], (root / set.models[i].path).string(), a->options,
                                       a->cache, true);
              });
          const std::vector<std::size_t> sample = sampled_models(set, a->per_class, a->seed);
          std::vector<PartQuery> tried(sample.size());
          const std::string parts_dir =
              a->parts.empty() ? "" : (fs::path(a->parts) / name).string();
          if (!parts_dir.empty()) fs::create_directories(parts_dir);
          argtool::run_with_progress("cut " + name, sample.size(), a->threads, [&](std::size_t k) {
            const std::size_t i = sample[k];
            tried[k] =
                make_query(i, (root / set.models[i].path).string(), models[i], *a, parts_dir);
          });
          std::vector<PartQuery> queries;
          for (auto& q : tried) {
            if (q.error.empty()) {
              queries.push_back(std::move(q));
            } else {
              std::fprintf(stderr, "no query: %s: %s: %s\n", name.c_str(),
                           set.models[q.source].path.c_str(), q.error.c_str());
            }
          }
          if (queries.empty()) throw std::runtime_error(name + ": no model gave a part query");
          const double prepare_s = ms_since(t0) / 1000.0;
          const std::size_t n = models.size(), nq = queries.size();
          std::vector<Method> methods = methods_of(*a);
          for (Method& m : methods) {
            m.distance.assign(nq * n, 0.0);
            m.matched.assign(nq * n, 0);
          }
          t0 = std::chrono::steady_clock::now();
          argtool::run_with_progress("rank " + name, nq, a->threads, [&](std::size_t k) {
            rank_query(k, queries[k], models, methods, *a);
          });
          const double rank_s = ms_since(t0) / 1000.0;
          std::vector<int> query_label(nq), query_self(nq);
          std::vector<bool> valid(n);
          for (std::size_t j = 0; j < n; ++j) valid[j] = models[j].error.empty();
          double faces = 0, area = 0;
          // Colour counts only when both sides have it (the shape and colour presets are the
          // arg preset on a set without any).
          std::size_t coloured = 0;
          for (const Model& m : models) coloured += m.error.empty() && m.graph.summary.has_colour;
          for (std::size_t k = 0; k < nq; ++k) {
            query_label[k] = set.class_of[queries[k].source];
            query_self[k] = int(queries[k].source);
            faces += double(queries[k].faces) / double(nq);
            area += queries[k].area / double(nq);
          }
          std::fprintf(stderr,
                       "%s: %zu part queries of %zu sampled models (level %d, %.0f triangles and "
                       "%.3f of the surface on average), %zu of %zu models coloured, %.1f s to "
                       "build and cut, %.1f s to rank\n",
                       name.c_str(), nq, sample.size(), a->level, faces, area, coloured, n,
                       prepare_s, rank_s);
          for (const Method& m : methods) {
            const arg::RetrievalScores s =
                arg::query_scores(m.distance, query_label, set.class_of, int(set.classes.size()),
                                  {}, valid, m.in_situ ? query_self : std::vector<int>{});
            // Part methods: the share of candidates with a match, and of the queries whose
            // source model held one (the cut part found where it came from).
            double matched = 0, source = 0, first = 0;
            if (!m.in_situ)
              for (std::size_t k = 0; k < nq; ++k) {
                // The source model ranked first (ties by index, as query_scores ranks).
                const double* row = m.distance.data() + k * n;
                const std::size_t self = queries[k].source;
                bool best = true;
                for (std::size_t j = 0; j < n && best; ++j)
                  best = !valid[j] || j == self || row[j] > row[self] ||
                         (row[j] == row[self] && j > self);
                first += best ? 1.0 / double(nq) : 0;
              }
            if (m.score == Score::part)
              for (std::size_t k = 0; k < nq; ++k) {
                std::size_t count = 0, of = 0;
                for (std::size_t j = 0; j < n; ++j)
                  if (valid[j] && !(m.in_situ && j == queries[k].source))
                    ++of, count += m.matched[k * n + j] != 0;
                matched += of ? double(count) / double(of) / double(nq) : 0;
                source += m.matched[k * n + queries[k].source] ? 1.0 / double(nq) : 0;
              }
            char matched_text[16] = "-", source_text[16] = "-", first_text[16] = "-";
            if (!m.in_situ) std::snprintf(first_text, sizeof first_text, "%.3f", first);
            if (m.score == Score::part)
              std::snprintf(matched_text, sizeof matched_text, "%.3f", matched);
            if (m.score == Score::part && !m.in_situ)
              std::snprintf(source_text, sizeof source_text, "%.3f", source);
            std::snprintf(line, sizeof line,
                          "%-10s %-26s %-11s %7zu %6.3f %6.3f %6.3f %7s %7s %7s %7.1f",
                          name.c_str(), m.query.c_str(), m.name.c_str(), nq, s.nn, s.ft, s.map,
                          matched_text, source_text, first_text, prepare_s + rank_s);
            table.push_back(line);
            nlohmann::json row = {{"set", name},
                                  {"query", m.query},
                                  {"method", m.name},
                                  {"queries", nq},
                                  {"sampled", sample.size()},
                                  {"level", a->level},
                                  {"nn", s.nn},
                                  {"ft", s.ft},
                                  {"map", s.map}};
            if (m.score == Score::part) row["matched"] = matched;
            if (m.score == Score::part && !m.in_situ) row["source_matched"] = source;
            if (!m.in_situ) row["source_first"] = first;
            nlohmann::json per_class;
            for (std::size_t c = 0; c < set.classes.size(); ++c)
              if (s.queries_per_class[c] > 0)
                per_class[set.classes[c]] = {{"queries", s.queries_per_class[c]},
                                             {"nn", s.nn_per_class[c]},
                                             {"ft", s.ft_per_class[c]}};
            row["per_class"] = per_class;
            out.push_back(row);
          }
        }
        for (const std::string& row : table) std::printf("%s\n", row.c_str());
        if (!a->json.empty()) argtool::write_file_bytes(a->json, out.dump(2) + "\n");
        return 0;
      };
    });

}  // namespace
