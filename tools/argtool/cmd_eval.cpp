// argtool eval: on each labelled set every model queries all the others; PSB measures per method.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "command_registry.hpp"
#include "eval/baseline_descriptors.hpp"
#include "eval/distance_matrix_file.hpp"
#include "eval/label_file.hpp"
#include "eval/pr_plot.hpp"
#include "eval/retrieval_metrics.hpp"
#include "eval/set_weights_file.hpp"
#include "eval_models.hpp"
#include "load_arg.hpp"
#include "match/match_prep.hpp"
#include "match/similarity.hpp"
#include "peer_matrices.hpp"
#include "per_class_table.hpp"
#include "progress_bar.hpp"

namespace fs = std::filesystem;

namespace {

struct EvalArgs {
  std::vector<std::string> labels, queries;
  std::string root, weights, cache, json, plot, matrix, weights_per_set, peers;
  std::vector<std::string> methods;
  bool per_class = false;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  arg::BuildOptions options;
};

using argtool::Model;

double median(std::vector<double> x) {
  if (x.empty()) return 0;
  std::sort(x.begin(), x.end());
  return x.size() % 2 ? x[x.size() / 2] : 0.5 * (x[x.size() / 2 - 1] + x[x.size() / 2]);
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// arg: SIM with --weights (default the arg preset); mrg: Hilaga's preset; graph: the graph
// alone (the graph preset, the ARG as it was before the whole-shape terms).
bool is_graph_method(const std::string& m) {
  return m == "arg" || m == "mrg" || m == "graph";
}

// The distance of one method between two prepared models.
struct MethodDistance {
  bool graph;
  arg::Weights weights;
  const arg::DescriptorMethod* descriptor;
  std::string name;

  MethodDistance(const std::string& method, const EvalArgs& a)
      : graph(is_graph_method(method)),
        weights(arg::parse_weights(method != "arg" && is_graph_method(method)
                                       ? method
                                       : (a.weights.empty() ? "arg" : a.weights))),
        descriptor(graph ? nullptr : arg::find_descriptor_method(method)),
        name(method) {}

  double operator()(const Model& x, const Model& y) const {
    return graph ? arg::arg_similarity(x.graph, y.graph, weights)
                 : descriptor->distance(x.descriptor.at(name), y.descriptor.at(name));
  }
  // Graph methods only: with each graph's MatchPrep (the same result, for less).
  double operator()(const Model& x, const arg::MatchPrep& px, const Model& y,
                    const arg::MatchPrep& py) const {
    return arg::arg_similarity(x.graph, y.graph, weights, nullptr, &px, &py);
  }
  // Each model's MatchPrep for these weights (empty for descriptor methods or failed models);
  // `us`, when given, receives each one's time in microseconds.
  std::vector<arg::MatchPrep> prepare(const std::vector<Model>& models, int threads,
                                      std::vector<double>* us = nullptr) const {
    std::vector<arg::MatchPrep> preps(models.size());
    if (us) us->assign(models.size(), 0.0);
    if (!graph) return preps;
    argtool::run_with_progress("prepare " + name, models.size(), threads, [&](std::size_t i) {
      if (!models[i].error.empty()) return;
      auto t0 = std::chrono::steady_clock::now();
      arg::prepare_match(models[i].graph, weights, preps[i]);
      if (us)
        (*us)[i] = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0)
                       .count();
    });
    return preps;
  }
};

struct MethodResult {
  arg::RetrievalScores scores;
  arg::DistanceMatrix matrix;
  double build_ms_median = 0, sim_us_median = 0, seconds = 0;
  std::size_t failed = 0;
};

MethodResult run_method(const std::string& method, const std::vector<Model>& models,
                        const arg::LabelSet& set, const EvalArgs& a) {
  auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = models.size();
  MethodResult r;
  r.matrix.n = n;
  r.matrix.distance.assign(n * n, 0.0);
  std::vector<double>& distance = r.matrix.distance;
  std::vector<double> row_us(n, 0.0);
  const bool graph = is_graph_method(method);
  const MethodDistance between(method, a);
  // Each graph's own part of matching, once (timed with the comparisons, spread over them).
  std::vector<double> prep_us;
  const std::vector<arg::MatchPrep> preps = between.prepare(models, a.threads, &prep_us);
  // Every distance is symmetric: each row computes the pairs to its right and mirrors them.
  argtool::run_with_progress("compare " + method, n, a.threads, [&](std::size_t i) {
    if (!models[i].error.empty()) return;
    auto r0 = std::chrono::steady_clock::now();
    std::size_t count = 0;
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!models[j].error.empty()) continue;
      const double d =
          graph ? between(models[i], preps[i], models[j], preps[j]) : between(models[i], models[j]);
      distance[i * n + j] = distance[j * n + i] = d;
      ++count;
    }
    if (count)
      row_us[i] =
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - r0).count() /
          double(count);
  });
  // The preparations count in the time a pair: their total spread evenly over every pair.
  std::size_t valid = 0;
  double prep_total = 0;
  for (std::size_t i = 0; i < n; ++i) valid += models[i].error.empty(), prep_total += prep_us[i];
  if (valid > 1)
    for (double& us : row_us)
      if (us > 0) us += prep_total / (0.5 * double(valid) * double(valid - 1));
  r.matrix.valid.resize(n);
  std::vector<double> builds, sims;
  for (std::size_t i = 0; i < n; ++i) {
    r.matrix.valid[i] = models[i].error.empty();
    if (!r.matrix.valid[i]) {
      ++r.failed;
      continue;
    }
    const double ms = graph ? models[i].build_ms : models[i].descriptor_ms.at(method);
    if (ms > 0) builds.push_back(ms);
    if (row_us[i] > 0) sims.push_back(row_us[i]);
  }
  r.scores = arg::retrieval_scores(distance, set.class_of, int(set.classes.size()), r.matrix.valid);
  r.build_ms_median = median(builds);
  r.sim_us_median = median(sims);
  r.seconds = ms_since(t0) / 1000.0;
  return r;
}

// Transformed copies (a --queries set) against the collection: q x n distances, scored.
arg::RetrievalScores run_queries(const std::string& method, const std::vector<Model>& queries,
                                 const arg::LabelSet& query_set, const std::vector<Model>& models,
                                 const arg::LabelSet& set, const EvalArgs& a) {
  const MethodDistance between(method, a);
  const std::size_t q = queries.size(), n = models.size();
  const std::vector<arg::MatchPrep> query_preps = between.prepare(queries, a.threads),
                                    model_preps = between.prepare(models, a.threads);
  std::vector<double> distance(q * n, 0.0);
  argtool::run_with_progress("query " + method, q, a.threads, [&](std::size_t i) {
    if (!queries[i].error.empty()) return;
    for (std::size_t j = 0; j < n; ++j)
      if (models[j].error.empty())
        distance[i * n + j] = between.graph
                                  ? between(queries[i], query_preps[i], models[j], model_preps[j])
                                  : between(queries[i], models[j]);
  });
  std::vector<int> query_label(q);
  std::vector<bool> query_valid(q), valid(n);
  for (std::size_t i = 0; i < q; ++i) {
    const auto c = std::find(set.classes.begin(), set.classes.end(), query_set.models[i].label);
    query_label[i] = c == set.classes.end() ? -1 : int(c - set.classes.begin());
    query_valid[i] = queries[i].error.empty();
  }
  for (std::size_t j = 0; j < n; ++j) valid[j] = models[j].error.empty();
  return arg::query_scores(distance, query_label, set.class_of, int(set.classes.size()),
                           query_valid, valid);
}

// FILE itself for one set and one method; FILE with ".SET.METHOD" before its extension else.
std::string matrix_path(const std::string& file, const std::string& set, const std::string& method,
                        bool single) {
  if (single) return file;
  fs::path p(file);
  const std::string ext = p.has_extension() ? p.extension().string() : ".txt";
  return (p.parent_path() / (p.stem().string() + "." + set + "." + method + ext)).string();
}

// The PSB measures of one row of the table, as JSON.
nlohmann::json scores_json(const arg::RetrievalScores& s) {
  return {{"nn", s.nn}, {"ft", s.ft}, {"st", s.st}, {"e", s.e}, {"dcg", s.dcg}, {"map", s.map}};
}

// Builds (or reads from the cache) everything the methods need for each model of a set.
std::vector<Model> prepare_models(const arg::LabelSet& set, const fs::path& root,
                                  const std::string& label, bool need_arg,
                                  const std::vector<std::string>& descriptors, const EvalArgs& a) {
  std::vector<Model> models(set.models.size());
  argtool::run_with_progress(label, models.size(), a.threads, [&](std::size_t i) {
    argtool::prepare_model(models[i], (root / set.models[i].path).string(), a.options, a.cache,
                           need_arg, descriptors);
  });
  return models;
}

// One set's per-class columns: arg under the training weights (`training`, already scored),
// under its fold's weights when `folds` has them, and each peer under the same scorer.
argtool::PerClassColumns per_class_columns(const std::string& name, const arg::LabelSet& set,
                                           const std::vector<Model>& models,
                                           const arg::RetrievalScores& training,
                                           const std::vector<arg::SetWeights>& folds,
                                           const EvalArgs& a) {
  argtool::PerClassColumns columns{name, &set, training, {}, {}, {}, {}, {}, {}};
  columns.training_label = a.weights.empty()
                               ? "the shipped weights, learnt on every set: a training score"
                               : "--weights " + a.weights;
  columns.training_weights =
      arg::format_weights(arg::parse_weights(a.weights.empty() ? "arg" : a.weights));
  const auto fold = std::find_if(folds.begin(), folds.end(),
                                 [&](const arg::SetWeights& f) { return f.set == name; });
  if (!folds.empty() && fold == folds.end())
    throw std::runtime_error(a.weights_per_set + " has no weights for set " + name);
  if (fold != folds.end()) {
    EvalArgs held = a;
    held.weights = fold->weights;
    columns.held_out = run_method("arg", models, set, held).scores;
    columns.held_out_weights = arg::format_weights(arg::parse_weights(fold->weights));
  }
  if (!a.peers.empty())
    for (auto& peer : argtool::read_peer_matrices(a.peers, name, models.size()))
      columns.peers.emplace_back(peer.method,
                                 arg::retrieval_scores(peer.matrix.distance, set.class_of,
                                                       int(set.classes.size()), peer.matrix.valid));
  return columns;
}

const bool registered = argtool::register_command(
    "eval",
    "retrieval quality on labelled sets (on each, every model queries all the others); one "
    "table, a row per set and method",
    [](CLI::App& app) {
      auto a = std::make_shared<EvalArgs>();
      app.add_option("--labels", a->labels,
                     "CSV with header model_id,path,class (repeatable: one table for all sets)")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("--root", a->root,
                     "folder the paths are relative to (default: each CSV's folder; one set only)");
      std::vector<std::string> names = {"arg", "mrg", "graph"};
      for (const auto& d : arg::descriptor_methods()) names.push_back(d.name);
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      app.add_option("--method", a->methods, list + " (repeatable; default arg)")
          ->check(CLI::IsMember(names));
      app.add_option("--weights", a->weights,
                     "weights of the arg method: preset or key=value text");
      app.add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 256));
      app.add_option("--cache", a->cache, "folder caching built ARGs between runs");
      app.add_option("--json", a->json, "write the scores as JSON (curves go to OUT.curves.json)");
      app.add_option("--plot", a->plot,
                     "write the precision-recall curves of the first set as SVG");
      app.add_option("--queries", a->queries,
                     "CSV of query models from outside the set (argtool perturb's folders): "
                     "each queries the one --labels set; a row per query set (repeatable)")
          ->check(CLI::ExistingFile);
      app.add_option("--matrix", a->matrix,
                     "write the distance matrix: a line per model in label order, failed models "
                     "inf (several sets or methods: FILE.SET.METHOD.txt)");
      app.add_flag(
          "--per-class", a->per_class,
          "also a table per set of each class's NN and FT under the arg method: held "
          "out (the set's --weights-per-set weights) beside training (--weights, "
          "default the shipped weights, learnt on every set) and each other --method's FT; "
          "with --json, the same "
          "numbers in OUT.per_class.json");
      app.add_option("--weights-per-set", a->weights_per_set,
                     "the held-out weights of --per-class: a line per set, 'SET WEIGHTS', as "
                     "`argtool tune --fold-weights FILE` writes them (each learnt on the other "
                     "sets; read from tune's file rather than searched here, since the folds "
                     "rebuild every set on proxies); without it the held-out columns show -")
          ->check(CLI::ExistingFile);
      app.add_option("--peers", a->peers,
                     "folder of the peers' matrices for --per-class, DIR/SET/METHOD.dist.txt.gz "
                     "(../shared/peers): each peer's FT per class beside arg's");
      argtool::add_build_flags(app, a->options, false);
      return [a] {
        if (a->methods.empty()) a->methods = {"arg"};
        if (a->per_class &&
            std::find(a->methods.begin(), a->methods.end(), "arg") == a->methods.end())
          throw std::runtime_error("--per-class reports the arg method: add --method arg");
        if (!a->per_class && (!a->weights_per_set.empty() || !a->peers.empty()))
          throw std::runtime_error("--weights-per-set and --peers go with --per-class");
        std::vector<arg::SetWeights> folds;
        if (!a->weights_per_set.empty())
          folds = arg::parse_set_weights(argtool::read_file_bytes(a->weights_per_set));
        if (!a->root.empty() && a->labels.size() > 1)
          throw std::runtime_error("--root applies to one labels file only");
        if (!a->queries.empty() && a->labels.size() != 1)
          throw std::runtime_error("--queries needs exactly one --labels set to query");
        if (!a->cache.empty()) fs::create_directories(a->cache);
        const bool single = a->labels.size() == 1 && a->methods.size() == 1;
        const bool need_arg = std::any_of(a->methods.begin(), a->methods.end(), is_graph_method);
        std::vector<std::string> descriptors;
        for (const auto& m : a->methods)
          if (!is_graph_method(m) &&
              std::find(descriptors.begin(), descriptors.end(), m) == descriptors.end())
            descriptors.push_back(m);
        nlohmann::json out = nlohmann::json::array(), curves = nlohmann::json::array();
        std::vector<arg::PrCurve> plot;
        std::vector<std::string> table, per_class_tables;
        nlohmann::json per_class = nlohmann::json::array();
        char line[256];
        std::snprintf(line, sizeof line, "%-10s %-7s %6s %6s %6s %6s %6s %6s %6s %6s %9s %9s %8s",
                      "set", "method", "models", "failed", "NN", "FT", "ST", "E", "DCG", "mAP",
                      "build_ms", "sim_us", "seconds");
        table.push_back(line);
        for (const std::string& labels : a->labels) {
          auto t0 = std::chrono::steady_clock::now();
          const std::string name = argtool::set_name(labels);
          arg::LabelSet set = arg::parse_label_csv(argtool::read_file_bytes(labels));
          fs::path root = a->root.empty() ? fs::path(labels).parent_path() : fs::path(a->root);
          std::vector<Model> models =
              prepare_models(set, root, "build " + name, need_arg, descriptors, *a);
          const double prepare_s = ms_since(t0) / 1000.0;
          for (std::size_t i = 0; i < models.size(); ++i)
            if (!models[i].error.empty())
              std::fprintf(stderr, "failed: %s: %s: %s\n", name.c_str(), set.models[i].path.c_str(),
                           models[i].error.c_str());
          std::vector<std::pair<std::string, arg::RetrievalScores>> others;
          std::optional<arg::RetrievalScores> arg_scores;
          for (const std::string& method : a->methods) {
            MethodResult r = run_method(method, models, set, *a);
            const auto& s = r.scores;
            if (method == "arg")
              arg_scores = s;
            else
              others.emplace_back(method, s);
            const double seconds = r.seconds + prepare_s;
            std::snprintf(line, sizeof line,
                          "%-10s %-7s %6zu %6zu %6.3f %6.3f %6.3f %6.3f %6.3f %6.3f %9.2f %9.2f "
                          "%8.1f",
                          name.c_str(), method.c_str(), models.size(), r.failed, s.nn, s.ft, s.st,
                          s.e, s.dcg, s.map, r.build_ms_median, r.sim_us_median, seconds);
            table.push_back(line);
            if (!a->matrix.empty())
              argtool::write_file_bytes(matrix_path(a->matrix, name, method, single),
                                        arg::format_distance_matrix(r.matrix));
            nlohmann::json failed = nlohmann::json::array();
            for (std::size_t i = 0; i < models.size(); ++i)
              if (!models[i].error.empty())
                failed.push_back({{"path", set.models[i].path}, {"error", models[i].error}});
            out.push_back({{"set", name},
                           {"labels", labels},
                           {"method", method},
                           {"models", models.size()},
                           {"classes", set.classes.size()},
                           {"failed", failed},
                           {"build_ms_median", r.build_ms_median},
                           {"sim_us_median", r.sim_us_median},
                           {"seconds", seconds}});
            out.back().update(scores_json(s));
            nlohmann::json per_class;
            for (std::size_t c = 0; c < set.classes.size(); ++c)
              per_class[set.classes[c]] = s.ft_per_class[c];
            curves.push_back({{"set", name},
                              {"method", method},
                              {"precision_at_recall", s.precision_at_recall},
                              {"ft_per_class", per_class}});
            if (labels == a->labels.front()) plot.push_back({method, s.precision_at_recall});
          }
          if (a->per_class) {
            argtool::PerClassColumns columns =
                per_class_columns(name, set, models, *arg_scores, folds, *a);
            columns.methods = others;
            per_class_tables.push_back(argtool::per_class_text(columns));
            per_class.push_back(argtool::per_class_json(columns));
          }
          for (const std::string& query_file : a->queries) {
            const arg::LabelSet query_set =
                arg::parse_label_csv(argtool::read_file_bytes(query_file));
            const std::string query_name = argtool::set_name(query_file);
            const std::vector<Model> queries =
                prepare_models(query_set, fs::path(query_file).parent_path(), "build " + query_name,
                               need_arg, descriptors, *a);
            std::size_t failed = 0;
            for (std::size_t i = 0; i < queries.size(); ++i)
              if (!queries[i].error.empty()) {
                ++failed;
                std::fprintf(stderr, "failed: %s: %s: %s\n", query_name.c_str(),
                             query_set.models[i].path.c_str(), queries[i].error.c_str());
              }
            for (const std::string& method : a->methods) {
              const auto s = run_queries(method, queries, query_set, models, set, *a);
              std::snprintf(line, sizeof line,
                            "%-10s %-7s %6zu %6zu %6.3f %6.3f %6.3f %6.3f %6.3f %6.3f %9s %9s %8s",
                            query_name.c_str(), method.c_str(), queries.size(), failed, s.nn, s.ft,
                            s.st, s.e, s.dcg, s.map, "", "", "");
              table.push_back(line);
              out.push_back({{"set", name},
                             {"queries", query_name},
                             {"method", method},
                             {"models", queries.size()},
                             {"failed", failed}});
              out.back().update(scores_json(s));
            }
          }
        }
        for (const std::string& row : table) std::printf("%s\n", row.c_str());
        for (const std::string& t : per_class_tables) std::printf("\n%s", t.c_str());
        if (!a->json.empty()) {
          argtool::write_file_bytes(a->json, (out.size() == 1 ? out[0] : out).dump(2) + "\n");
          fs::path side = fs::path(a->json).replace_extension(".curves.json");
          argtool::write_file_bytes(side.string(),
                                    (curves.size() == 1 ? curves[0] : curves).dump(2) + "\n");
          if (a->per_class)
            argtool::write_file_bytes(
                fs::path(a->json).replace_extension(".per_class.json").string(),
                (per_class.size() == 1 ? per_class[0] : per_class).dump(2) + "\n");
        }
        if (!a->plot.empty())
          argtool::write_file_bytes(
              a->plot, arg::precision_recall_svg(
                           plot, "Precision-recall: " + argtool::set_name(a->labels.front())));
        return 0;
      };
    });

}  // namespace
