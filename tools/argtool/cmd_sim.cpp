// argtool sim: SIM between two models, optionally with the matched node pairs.
#include <cstdio>
#include <iostream>
#include <memory>

#include "command_registry.hpp"
#include "load_arg.hpp"
#include "match/similarity.hpp"

namespace {

struct SimArgs {
  std::string a, b, weights = "arg";
  bool explain = false;
  arg::BuildOptions options;
};

const bool registered = argtool::register_command(
    "sim", "SIM between two models (ARG or mesh files); 0 = same shape", [](CLI::App& app) {
      auto a = std::make_shared<SimArgs>();
      app.add_option("a", a->a, "first model")->required()->check(CLI::ExistingFile);
      app.add_option("b", a->b, "second model")->required()->check(CLI::ExistingFile);
      app.add_option("--weights", a->weights,
                     "preset (arg, part, mrg, graph, shape, colour) or key=value text");
      app.add_flag("--explain", a->explain, "the terms of SIM and the graph's matched node pairs");
      argtool::add_build_flags(app, a->options);
      return [a] {
        arg::Weights w = arg::parse_weights(a->weights);
        argtool::LoadedArg x = argtool::load_arg(a->a, a->options),
                           y = argtool::load_arg(a->b, a->options);
        std::vector<arg::MatchPair> pairs;
        double s = arg::arg_similarity(x.graph, y.graph, w, a->explain ? &pairs : nullptr);
        std::printf("%.6f\n", s);
        if (a->explain) {
          const arg::SimilarityParts p = arg::similarity_parts(x.graph, y.graph, w);
          std::printf(
              "graph %.6f (weight %g)  panorama %.6f (weight %g)  spectrum %.6f (weight %g)\n",
              p.graph, p.w_graph, p.panorama, p.w_panorama, p.spectrum, p.w_spectrum);
          std::printf("level  a_node  b_node  group      loss       sim\n");
          for (const auto& p : pairs)
            std::printf("%5d  %6d  %6d  %5d  %8.5f  %8.5f\n", p.level, p.a_node, p.b_node, p.group,
                        p.loss, p.sim);
        }
        return 0;
      };
    });

}  // namespace
