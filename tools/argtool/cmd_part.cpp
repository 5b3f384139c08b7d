// argtool part: find the part of a query model (one node) in candidate models.
#include <cstdio>
#include <memory>

#include "command_registry.hpp"
#include "load_arg.hpp"
#include "match/similarity.hpp"

namespace {

struct PartArgs {
  std::string query, weights = "part";
  std::vector<std::string> candidates;
  int level = 2, node = 0, top = 5;
  double threshold = 0.5;
  arg::BuildOptions options;
};

const bool registered = argtool::register_command(
    "part", "rank the parts of candidate models that match one node of a query", [](CLI::App& app) {
      auto a = std::make_shared<PartArgs>();
      app.add_option("query", a->query, "query model (ARG or mesh)")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("candidates", a->candidates, "candidate models")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("--level", a->level, "level of the query node")->required();
      app.add_option("--node", a->node, "index of the query node within its level")->required();
      app.add_option("--weights", a->weights, "preset or key=value text");
      app.add_option("--threshold", a->threshold, "node similarity needed to be compared (0..1)");
      app.add_option("--top", a->top, "parts listed per candidate");
      argtool::add_build_flags(app, a->options);
      return [a] {
        arg::Weights w = arg::parse_weights(a->weights);
        argtool::LoadedArg q = argtool::load_arg(a->query, a->options);
        std::printf("%-40s %5s %5s %9s\n", "candidate", "level", "node", "score");
        for (const auto& path : a->candidates) {
          argtool::LoadedArg c = argtool::load_arg(path, a->options);
          auto parts = arg::part_match(q.graph, a->level, a->node, c.graph, w, a->threshold);
          for (std::size_t k = 0; k < parts.size() && int(k) < a->top; ++k)
            std::printf("%-40s %5d %5d %9.6f\n", path.c_str(), parts[k].level, parts[k].node,
                        parts[k].score);
        }
        return 0;
      };
    });

}  // namespace
