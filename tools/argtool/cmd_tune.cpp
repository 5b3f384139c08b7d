// argtool tune: learn the weights on training folds, report mAP on the held-out folds.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <thread>

#include "command_registry.hpp"
#include "eval/label_file.hpp"
#include "eval/retrieval_metrics.hpp"
#include "eval/weight_search.hpp"
#include "eval_models.hpp"
#include "load_arg.hpp"
#include "match/similarity.hpp"
#include "progress_bar.hpp"

namespace fs = std::filesystem;

namespace {

struct TuneArgs {
  std::string labels, root, cache, start = "arg";
  int folds = 2, rounds = 3;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  arg::BuildOptions options;
};

// Retrieval scores when the models `members` query each other only.
arg::RetrievalScores scores_within(const std::vector<argtool::Model>& models,
                                   const arg::LabelSet& set, const std::vector<int>& members,
                                   const arg::Weights& w, int threads) {
  const std::size_t n = members.size();
  std::vector<double> distance(n * n, 0.0);
  std::vector<int> label(n);
  std::vector<bool> valid(n);
  for (std::size_t i = 0; i < n; ++i) {
    label[i] = set.class_of[std::size_t(members[i])];
    valid[i] = models[std::size_t(members[i])].error.empty();
  }
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++)
      for (std::size_t j = i + 1; j < n; ++j)
        if (valid[i] && valid[j])
          distance[i * n + j] = distance[j * n + i] = arg::arg_similarity(
              models[std::size_t(members[i])].graph, models[std::size_t(members[j])].graph, w);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return arg::retrieval_scores(distance, label, int(set.classes.size()), valid);
}

const bool registered = argtool::register_command(
    "tune", "learn the matching weights (coordinate search on mAP) with cross-validation",
    [](CLI::App& app) {
      auto a = std::make_shared<TuneArgs>();
      app.add_option("--labels", a->labels, "CSV with header model_id,path,class")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("--root", a->root,
                     "folder the paths are relative to (default: the CSV's folder)");
      app.add_option("--folds", a->folds, "cross-validation folds (stratified by class)")
          ->check(CLI::Range(2, 10));
      app.add_option("--rounds", a->rounds, "passes of the coordinate search")
          ->check(CLI::Range(1, 10));
      app.add_option("--start", a->start, "weights to start from (preset or key=value text)");
      app.add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 256));
      app.add_option("--cache", a->cache, "folder caching built ARGs between runs");
      argtool::add_build_flags(app, a->options, false);
      return [a] {
        arg::LabelSet set = arg::parse_label_csv(argtool::read_file_bytes(a->labels));
        fs::path root = a->root.empty() ? fs::path(a->labels).parent_path() : fs::path(a->root);
        if (!a->cache.empty()) fs::create_directories(a->cache);
        std::vector<argtool::Model> models(set.models.size());
        argtool::run_with_progress("build", models.size(), a->threads, [&](std::size_t i) {
          argtool::prepare_model(models[i], (root / set.models[i].path).string(), a->options,
                                 a->cache, true, false, false);
        });
        // Stratified folds: the k-th model of each class goes to fold k mod folds.
        std::vector<int> fold(models.size()), seen(set.classes.size(), 0);
        for (std::size_t i = 0; i < models.size(); ++i)
          fold[i] = seen[std::size_t(set.class_of[i])]++ % a->folds;
        const arg::Weights start = arg::parse_weights(a->start);
        auto say = [](const std::string& line) { std::fprintf(stderr, "  %s\n", line.c_str()); };
        double held_out_sum = 0, baseline_sum = 0;
        for (int f = 0; f < a->folds; ++f) {
          std::vector<int> train, test;
          for (std::size_t i = 0; i < models.size(); ++i)
            (fold[i] == f ? test : train).push_back(int(i));
          std::fprintf(stderr, "fold %d: training on %zu models\n", f + 1, train.size());
          arg::Weights learnt = arg::search_weights(
              start,
              [&](const arg::Weights& w) {
                return scores_within(models, set, train, w, a->threads).map;
              },
              a->rounds, 1e-4, say);
          const double held = scores_within(models, set, test, learnt, a->threads).map;
          const double base = scores_within(models, set, test, start, a->threads).map;
          held_out_sum += held, baseline_sum += base;
          std::printf("fold %d: held-out mAP %.4f (start weights %.4f) with %s\n", f + 1, held,
                      base, arg::format_weights(learnt).c_str());
        }
        std::printf("cross-validated mAP %.4f (start weights %.4f) over %d folds\n",
                    held_out_sum / a->folds, baseline_sum / a->folds, a->folds);
        std::vector<int> all(models.size());
        for (std::size_t i = 0; i < all.size(); ++i) all[i] = int(i);
        std::fprintf(stderr, "final: training on all %zu models\n", all.size());
        arg::Weights final_weights = arg::search_weights(
            start,
            [&](const arg::Weights& w) {
              return scores_within(models, set, all, w, a->threads).map;
            },
            a->rounds, 1e-4, say);
        std::printf(
            "learnt weights (all models; use the cross-validated mAP above as their honest "
            "score):\n%s\n",
            arg::format_weights(final_weights).c_str());
        return 0;
      };
    });

}  // namespace
