// argtool tune: learn the weights on some models or sets, report the scores on the ones held out.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <thread>

#include "command_registry.hpp"
#include "common/parallel_for.hpp"
#include "eval/label_file.hpp"
#include "eval/retrieval_metrics.hpp"
#include "eval/set_weights_file.hpp"
#include "eval/term_matrices.hpp"
#include "eval/weight_search.hpp"
#include "eval_models.hpp"
#include "load_arg.hpp"
#include "match/similarity.hpp"
#include "progress_bar.hpp"

namespace fs = std::filesystem;

namespace {

struct TuneArgs {
  std::vector<std::string> labels;
  std::string root, cache, start = "arg", objective = "map", fold_weights, start_per_set, only;
  int folds = 2, rounds = 3;
  bool mixing_only = false, proxy_copies = false;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  arg::BuildOptions options;
};

// One labelled set with its models and the pairwise distances that do not depend on weights.
struct Set {
  std::string name;
  int copy_of = -1;  // a --proxy-copies set: the index of the set it copies
  arg::LabelSet labels;
  std::vector<argtool::Model> models;
  arg::TermMatrices terms;  // the whole-shape terms of every pair, which weights only mix
};

// Graph SIM matrices of every set for one choice of the graph's own weights, kept between the
// objective's calls: the mixing weights only recombine them.
class GraphCache {
 public:
  GraphCache(const std::vector<Set>& sets, int threads) : sets_(sets), threads_(threads) {}

  const std::vector<double>& get(std::size_t set, const std::vector<int>& members,
                                 const arg::Weights& w) {
    arg::Weights key_weights = w;
    key_weights.graph = 1, key_weights.panorama = key_weights.spectrum = 0;
    const std::string key = std::to_string(set) + "/" + std::to_string(members.size()) + "/" +
                            std::to_string(members.empty() ? -1 : members.front()) + "/" +
                            arg::format_weights(key_weights);
    auto found = cache_.find(key);
    if (found != cache_.end()) return found->second;
    if (cache_.size() > 64) cache_.clear();
    const auto& models = sets_[set].models;
    const std::size_t n = members.size();
    std::vector<double> d(n * n, 0.0);
    // Row i writes the pairs (i, j > i) and their mirrors, slots no other row writes.
    arg::parallel_for(n, threads_, [&](std::size_t i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const auto& a = models[std::size_t(members[i])];
        const auto& b = models[std::size_t(members[j])];
        if (a.error.empty() && b.error.empty())
          d[i * n + j] = d[j * n + i] = arg::graph_similarity(a.graph, b.graph, key_weights);
      }
    });
    return cache_[key] = std::move(d);
  }

 private:
  const std::vector<Set>& sets_;
  int threads_;
  std::map<std::string, std::vector<double>> cache_;
};

// Retrieval scores of `members` of one set querying each other, with SIM combined as
// arg_similarity does.
arg::RetrievalScores scores_within(const Set& s, const std::vector<int>& members,
                                   const arg::Weights& w, GraphCache& graphs, std::size_t index) {
  const std::size_t n = members.size();
  std::vector<double> distance(n * n, 0.0);
  std::vector<int> label(n);
  std::vector<bool> valid(n);
  // The graph's SIMs are computed only when some pair gives the graph a weight.
  bool need_graph = false;
  for (std::size_t i = 0; i < n && !need_graph; ++i)
    for (std::size_t j = 0; j < n && !need_graph; ++j)
      need_graph = i != j && arg::pair_term_weights(s.terms, std::size_t(members[i]),
                                                    std::size_t(members[j]), w)
                                     .graph > 0;
  const std::vector<double>* g = need_graph ? &graphs.get(index, members, w) : nullptr;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t mi = std::size_t(members[i]);
    label[i] = s.labels.class_of[mi];
    valid[i] = s.models[mi].error.empty();
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      distance[i * n + j] =
          arg::mixed_similarity(s.terms, mi, std::size_t(members[j]), w, g ? (*g)[i * n + j] : 0.0);
    }
  }
  return arg::retrieval_scores(distance, label, int(s.labels.classes.size()), valid);
}

double objective_of(const arg::RetrievalScores& r, const std::string& objective) {
  return objective == "psb" ? (r.nn + r.ft + r.dcg) / 3.0 : r.map;
}

std::string row(const char* what, const std::string& set, const arg::RetrievalScores& r) {
  char line[200];
  std::snprintf(line, sizeof line, "%-26s %-10s NN %.3f  FT %.3f  ST %.3f  DCG %.3f  mAP %.3f",
                what, set.c_str(), r.nn, r.ft, r.st, r.dcg, r.map);
  return line;
}

// --only's weight and the values to try for it.
struct OnlyWeight {
  std::string name;  // empty: no --only
  std::vector<float> values;
};

OnlyWeight parse_only(const std::string& text) {
  OnlyWeight only;
  if (text.empty()) return only;
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw std::runtime_error("--only wants NAME=V1,V2,...: got '" + text + "'");
  only.name = text.substr(0, eq);
  std::size_t at = eq + 1;
  while (at <= text.size()) {
    const auto comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    std::size_t used = 0;
    float value = 0;
    try {
      value = std::stof(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size() || !std::isfinite(value) || value < 0)
      throw std::runtime_error("--only: '" + item + "' is not a weight (a number, at least 0)");
    only.values.push_back(value);
    at = comma + 1;
  }
  return only;
}

std::vector<int> everyone(const Set& s) {
  std::vector<int> all(s.models.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  return all;
}

const bool registered = argtool::register_command(
    "tune",
    "learn the weights (coordinate search): with several sets, leave one set out and score on "
    "it; with one, cross-validate over folds",
    [](CLI::App& app) {
      auto a = std::make_shared<TuneArgs>();
      app.add_option("--labels", a->labels, "CSV with header model_id,path,class (repeatable)")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("--root", a->root,
                     "folder the paths are relative to (default: each CSV's folder; one set only)");
      app.add_option("--folds", a->folds, "cross-validation folds with one set (stratified)")
          ->check(CLI::Range(2, 10));
      app.add_option("--rounds", a->rounds, "passes of the coordinate search")
          ->check(CLI::Range(1, 10));
      app.add_option("--start", a->start, "weights to start from (preset or key=value text)");
      app.add_option("--objective", a->objective,
                     "map (mean average precision) or psb (mean of NN, FT and DCG), averaged "
                     "over the training sets")
          ->check(CLI::IsMember({"map", "psb"}));
      app.add_flag("--mixing-only", a->mixing_only,
                   "search only the graph, panorama, spectrum and graph_on_proxy weights, on a "
                   "grid (the graph's own weights stay as in --start)");
      app.add_flag("--proxy-copies", a->proxy_copies,
                   "also build every set on watertight proxies (surface=proxy) and train on "
                   "those copies too (never on the copy of a held-out set), so that "
                   "graph_on_proxy is learnt from proxies of the training shapes");
      app.add_option("--only", a->only,
                     "search one weight over listed values, the others held as started: "
                     "NAME=V1,V2,... (ties go to the first value: list the one without the term "
                     "first)");
      app.add_option("--start-per-set", a->start_per_set,
                     "each leave-one-set-out fold starts from its held-out set's line of this "
                     "file (what --fold-weights writes); the final search starts from --start")
          ->check(CLI::ExistingFile);
      app.add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 256));
      app.add_option("--cache", a->cache, "folder caching built ARGs between runs");
      app.add_option("--fold-weights", a->fold_weights,
                     "write the weights each leave-one-set-out fold learnt, a line per held-out "
                     "set (what eval --weights-per-set reads)");
      argtool::add_build_flags(app, a->options, false);
      return [a] {
        if (!a->root.empty() && a->labels.size() > 1)
          throw std::runtime_error("--root applies to one labels file only");
        if (a->proxy_copies && a->labels.size() < 2)
          throw std::runtime_error("--proxy-copies needs several --labels sets (leave one out)");
        if (!a->fold_weights.empty() && a->labels.size() < 2)
          throw std::runtime_error("--fold-weights needs several --labels sets (leave one out)");
        // Refused before the builds, which take minutes.
        const OnlyWeight only = parse_only(a->only);
        if (!only.name.empty()) {
          if (a->mixing_only)
            throw std::runtime_error("--only and --mixing-only are two searches: give one");
          arg::search_one_weight(arg::parse_weights(a->start), only.name, only.values,
                                 [](const arg::Weights&) { return 0.0; });
        }
        if (!a->start_per_set.empty() && a->labels.size() < 2)
          throw std::runtime_error("--start-per-set needs several --labels sets (leave one out)");
        if (!a->cache.empty()) fs::create_directories(a->cache);
        const std::size_t given = a->labels.size();
        std::vector<Set> sets(a->proxy_copies ? 2 * given : given);
        for (std::size_t k = 0; k < sets.size(); ++k) {
          Set& s = sets[k];
          const std::size_t source = k % given;
          const fs::path p(a->labels[source]);
          s.name = argtool::set_name(a->labels[source]);
          arg::BuildOptions options = a->options;
          if (k >= given) {
            s.copy_of = int(source);
            s.name += "/proxy";
            options.surface = arg::SurfaceKind::Proxy;
          }
          s.labels = arg::parse_label_csv(argtool::read_file_bytes(a->labels[source]));
          const fs::path root = a->root.empty() ? p.parent_path() : fs::path(a->root);
          s.models.resize(s.labels.models.size());
          argtool::run_with_progress(
              "build " + s.name, s.models.size(), a->threads, [&](std::size_t i) {
                argtool::prepare_model(s.models[i], (root / s.labels.models[i].path).string(),
                                       options, a->cache, true);
              });
          std::vector<const arg::ArgGraph*> built(s.models.size(), nullptr);
          for (std::size_t i = 0; i < s.models.size(); ++i)
            if (s.models[i].error.empty()) built[i] = &s.models[i].graph;
          s.terms = arg::term_matrices(built);
        }
        GraphCache graphs(sets, a->threads);
        const arg::Weights start = arg::parse_weights(a->start);
        std::map<std::string, arg::Weights> fold_start;
        if (!a->start_per_set.empty()) {
          for (const arg::SetWeights& f :
               arg::parse_set_weights(argtool::read_file_bytes(a->start_per_set)))
            fold_start[f.set] = arg::parse_weights(f.weights);
          for (std::size_t k = 0; k < given; ++k)
            if (!fold_start.count(sets[k].name))
              throw std::runtime_error(a->start_per_set + ": no weights for the fold holding out " +
                                       sets[k].name);
        }
        auto say = [](const std::string& line) { std::fprintf(stderr, "  %s\n", line.c_str()); };
        auto search = [&](const std::function<double(const arg::Weights&)>& objective,
                          const arg::Weights& from) {
          if (!only.name.empty())
            return arg::search_one_weight(from, only.name, only.values, objective);
          return a->mixing_only ? arg::grid_search_mixing(from, objective)
                                : arg::search_weights(from, objective, a->rounds, 1e-4, say);
        };
        std::vector<std::string> report;

        if (given == 1) {
          // Stratified folds: the k-th model of each class goes to fold k mod folds.
          const Set& s = sets[0];
          std::vector<int> fold(s.models.size()), seen(s.labels.classes.size(), 0);
          for (std::size_t i = 0; i < s.models.size(); ++i)
            fold[i] = seen[std::size_t(s.labels.class_of[i])]++ % a->folds;
          double held_sum = 0, base_sum = 0;
          for (int f = 0; f < a->folds; ++f) {
            std::vector<int> train, test;
            for (std::size_t i = 0; i < s.models.size(); ++i)
              (fold[i] == f ? test : train).push_back(int(i));
            std::fprintf(stderr, "fold %d: training on %zu models\n", f + 1, train.size());
            const arg::Weights learnt = search(
                [&](const arg::Weights& w) {
                  return objective_of(scores_within(s, train, w, graphs, 0), a->objective);
                },
                start);
            const double held = scores_within(s, test, learnt, graphs, 0).map;
            const double base = scores_within(s, test, start, graphs, 0).map;
            held_sum += held, base_sum += base;
            std::printf("fold %d: held-out mAP %.4f (start weights %.4f) with %s\n", f + 1, held,
                        base, arg::format_weights(learnt).c_str());
          }
          std::printf("cross-validated mAP %.4f (start weights %.4f) over %d folds\n",
                      held_sum / a->folds, base_sum / a->folds, a->folds);
        } else {
          // Leave one set out: learn on the others and their proxy copies (each weighs the
          // same), score on it.
          std::vector<arg::SetWeights> folds;
          for (std::size_t out = 0; out < given; ++out) {
            std::fprintf(stderr, "held out: %s\n", sets[out].name.c_str());
            std::vector<std::size_t> train;
            for (std::size_t k = 0; k < sets.size(); ++k)
              if (k != out && sets[k].copy_of != int(out)) train.push_back(k);
            const auto found = fold_start.find(sets[out].name);
            const arg::Weights& from = found == fold_start.end() ? start : found->second;
            const arg::Weights learnt = search(
                [&](const arg::Weights& w) {
                  double sum = 0;
                  for (std::size_t k : train)
                    sum += objective_of(scores_within(sets[k], everyone(sets[k]), w, graphs, k),
                                        a->objective);
                  const double mean = sum / double(train.size());
                  if (!only.name.empty())
                    std::fprintf(stderr, "  %s: training objective %.4f\n",
                                 arg::format_weights(w).c_str(), mean);
                  return mean;
                },
                from);
            const auto held = scores_within(sets[out], everyone(sets[out]), learnt, graphs, out);
            const auto base = scores_within(sets[out], everyone(sets[out]), from, graphs, out);
            report.push_back(row("held out, learnt weights", sets[out].name, held));
            report.push_back(row("held out, start weights", sets[out].name, base));
            report.push_back("  learnt on the other sets: " + arg::format_weights(learnt));
            folds.push_back({sets[out].name, arg::format_weights(learnt)});
            std::printf("%s\n%s\n%s\n", report[report.size() - 3].c_str(),
                        report[report.size() - 2].c_str(), report.back().c_str());
            std::fflush(stdout);
          }
          // Written as soon as the folds are done: the final search on everything is not needed.
          if (!a->fold_weights.empty())
            argtool::write_file_bytes(a->fold_weights, arg::format_set_weights(folds));
        }
        std::fprintf(stderr, "final: training on every model of every set\n");
        const arg::Weights final_weights = search(
            [&](const arg::Weights& w) {
              double sum = 0;
              for (std::size_t k = 0; k < sets.size(); ++k)
                sum += objective_of(scores_within(sets[k], everyone(sets[k]), w, graphs, k),
                                    a->objective);
              return sum / double(sets.size());
            },
            start);
        for (std::size_t k = 0; k < sets.size(); ++k)
          std::printf("%s\n",
                      row("training (all sets)", sets[k].name,
                          scores_within(sets[k], everyone(sets[k]), final_weights, graphs, k))
                          .c_str());
        std::printf(
            "learnt weights (all models; their scores above are training scores, the held-out "
            "ones are the honest figures):\n%s\n",
            arg::format_weights(final_weights).c_str());
        return 0;
      };
    });

}  // namespace
