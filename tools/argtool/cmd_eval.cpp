// argtool eval: every model of a labelled set queries all the others; PSB measures per method.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "command_registry.hpp"
#include "common/hash.hpp"
#include "eval/baseline_descriptors.hpp"
#include "eval/label_file.hpp"
#include "eval/pr_plot.hpp"
#include "eval/retrieval_metrics.hpp"
#include "eval_models.hpp"
#include "graph/serialize.hpp"
#include "load_arg.hpp"
#include "match/similarity.hpp"
#include "progress_bar.hpp"

namespace fs = std::filesystem;

namespace {

struct EvalArgs {
  std::string labels, root, weights, cache, json, plot;
  std::vector<std::string> methods;
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

struct MethodResult {
  std::string name;
  arg::RetrievalScores scores;
  double build_ms_median = 0, sim_us_median = 0, seconds = 0;
};

MethodResult run_method(const std::string& method, const std::vector<Model>& models,
                        const arg::LabelSet& set, const EvalArgs& a) {
  auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = models.size();
  std::vector<double> distance(n * n, 0.0);
  std::vector<double> row_us(n, 0.0);
  arg::Weights w =
      arg::parse_weights(method == "mrg" ? "mrg" : (a.weights.empty() ? "arg" : a.weights));
  // SIM and L1 are symmetric: each row computes the pairs to its right and mirrors them.
  argtool::run_with_progress("compare " + method, n, a.threads, [&](std::size_t i) {
    if (!models[i].error.empty()) return;
    auto r0 = std::chrono::steady_clock::now();
    std::size_t count = 0;
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!models[j].error.empty()) continue;
      double d;
      if (method == "d2")
        d = arg::l1_distance(models[i].d2, models[j].d2);
      else if (method == "cords")
        d = arg::l1_distance(models[i].cords, models[j].cords);
      else
        d = arg::arg_similarity(models[i].graph, models[j].graph, w);
      distance[i * n + j] = distance[j * n + i] = d;
      ++count;
    }
    if (count)
      row_us[i] =
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - r0).count() /
          double(count);
  });
  std::vector<bool> valid(n);
  std::vector<double> builds, sims;
  for (std::size_t i = 0; i < n; ++i) {
    valid[i] = models[i].error.empty();
    if (!valid[i]) continue;
    builds.push_back(method == "d2"      ? models[i].d2_ms
                     : method == "cords" ? models[i].cords_ms
                                         : models[i].build_ms);
    if (row_us[i] > 0) sims.push_back(row_us[i]);
  }
  MethodResult r;
  r.name = method;
  r.scores = arg::retrieval_scores(distance, set.class_of, int(set.classes.size()), valid);
  r.build_ms_median = median(builds);
  r.sim_us_median = median(sims);
  r.seconds = ms_since(t0) / 1000.0;
  return r;
}

const bool registered = argtool::register_command(
    "eval", "retrieval quality on a labelled set (every model queries all the others)",
    [](CLI::App& app) {
      auto a = std::make_shared<EvalArgs>();
      app.add_option("--labels", a->labels, "CSV with header model_id,path,class")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("--root", a->root,
                     "folder the paths are relative to (default: the CSV's folder)");
      app.add_option("--method", a->methods, "arg, mrg, d2 or cords (repeatable; default arg)")
          ->check(CLI::IsMember({"arg", "mrg", "d2", "cords"}));
      app.add_option("--weights", a->weights,
                     "weights of the arg method: preset or key=value text");
      app.add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 256));
      app.add_option("--cache", a->cache, "folder caching built ARGs between runs");
      app.add_option("--json", a->json, "write the scores as JSON (curves go to OUT.curves.json)");
      app.add_option("--plot", a->plot, "write the precision-recall curves as SVG");
      argtool::add_build_flags(app, a->options, false);
      return [a] {
        auto t0 = std::chrono::steady_clock::now();
        if (a->methods.empty()) a->methods = {"arg"};
        arg::LabelSet set = arg::parse_label_csv(argtool::read_file_bytes(a->labels));
        fs::path root = a->root.empty() ? fs::path(a->labels).parent_path() : fs::path(a->root);
        if (!a->cache.empty()) fs::create_directories(a->cache);
        auto uses = [&](const char* m) {
          return std::count(a->methods.begin(), a->methods.end(), m) > 0;
        };
        const bool need_arg = uses("arg") || uses("mrg");
        std::vector<Model> models(set.models.size());
        argtool::run_with_progress("build", models.size(), a->threads, [&](std::size_t i) {
          argtool::prepare_model(models[i], (root / set.models[i].path).string(), a->options,
                                 a->cache, need_arg, uses("d2"), uses("cords"));
        });
        const double prepare_s = ms_since(t0) / 1000.0;
        nlohmann::json out = nlohmann::json::array(), curves = nlohmann::json::array();
        std::vector<arg::PrCurve> plot;
        std::printf("%-8s %6s %6s %6s %6s %6s %6s %6s %9s %9s %8s\n", "method", "models", "NN",
                    "FT", "ST", "E", "DCG", "mAP", "build_ms", "sim_us", "seconds");
        for (const std::string& method : a->methods) {
          MethodResult r = run_method(method, models, set, *a);
          const auto& s = r.scores;
          const double seconds = r.seconds + prepare_s;
          std::printf("%-8s %6zu %6.3f %6.3f %6.3f %6.3f %6.3f %6.3f %9.2f %9.2f %8.1f\n",
                      method.c_str(), models.size(), s.nn, s.ft, s.st, s.e, s.dcg, s.map,
                      r.build_ms_median, r.sim_us_median, seconds);
          nlohmann::json failed = nlohmann::json::array();
          for (std::size_t i = 0; i < models.size(); ++i)
            if (!models[i].error.empty())
              failed.push_back({{"path", set.models[i].path}, {"error", models[i].error}});
          out.push_back({{"method", method},
                         {"models", models.size()},
                         {"classes", set.classes.size()},
                         {"failed", failed},
                         {"nn", s.nn},
                         {"ft", s.ft},
                         {"st", s.st},
                         {"e", s.e},
                         {"dcg", s.dcg},
                         {"map", s.map},
                         {"build_ms_median", r.build_ms_median},
                         {"sim_us_median", r.sim_us_median},
                         {"seconds", seconds}});
          nlohmann::json per_class;
          for (std::size_t c = 0; c < set.classes.size(); ++c)
            per_class[set.classes[c]] = s.ft_per_class[c];
          curves.push_back({{"method", method},
                            {"precision_at_recall", s.precision_at_recall},
                            {"ft_per_class", per_class}});
          plot.push_back({method, s.precision_at_recall});
        }
        for (std::size_t i = 0; i < models.size(); ++i)
          if (!models[i].error.empty())
            std::fprintf(stderr, "failed: %s: %s\n", set.models[i].path.c_str(),
                         models[i].error.c_str());
        if (!a->json.empty()) {
          argtool::write_file_bytes(a->json, (out.size() == 1 ? out[0] : out).dump(2) + "\n");
          fs::path side = fs::path(a->json).replace_extension(".curves.json");
          argtool::write_file_bytes(side.string(),
                                    (curves.size() == 1 ? curves[0] : curves).dump(2) + "\n");
        }
        if (!a->plot.empty())
          argtool::write_file_bytes(
              a->plot, arg::precision_recall_svg(
                           plot, "Precision-recall: " + fs::path(a->labels).filename().string()));
        return 0;
      };
    });

}  // namespace
