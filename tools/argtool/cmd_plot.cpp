// argtool plot: precision-recall curves from the curve files written by `argtool eval --json`.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "command_registry.hpp"
#include "eval/pr_plot.hpp"

namespace {

struct PlotArgs {
  std::vector<std::string> inputs;
  std::string output, title = "Precision-recall";
};

const bool registered = argtool::register_command(
    "plot", "draw precision-recall curves from eval JSON files as SVG", [](CLI::App& app) {
      auto a = std::make_shared<PlotArgs>();
      app.add_option("inputs", a->inputs,
                     "OUT.json files of argtool eval (their .curves.json is read)")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("-o,--output", a->output, "SVG to write")->required();
      app.add_option("--title", a->title, "chart title");
      return [a] {
        std::vector<arg::PrCurve> curves;
        for (const auto& path : a->inputs) {
          std::filesystem::path side =
              std::filesystem::path(path).replace_extension(".curves.json");
          nlohmann::json j = nlohmann::json::parse(argtool::read_file_bytes(side.string()));
          if (!j.is_array()) j = nlohmann::json::array({j});
          for (const auto& c : j)
            curves.push_back({c.at("method").get<std::string>(),
                              c.at("precision_at_recall").get<std::vector<double>>()});
        }
        argtool::write_file_bytes(a->output, arg::precision_recall_svg(curves, a->title));
        return 0;
      };
    });

}  // namespace
