// argtool perturb: transformed copies of a labelled set for the robustness benchmark.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "command_registry.hpp"
#include "eval/label_file.hpp"
#include "eval/perturbations.hpp"
#include "gen/seeded_random.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "progress_bar.hpp"

namespace fs = std::filesystem;

namespace {

struct PerturbArgs {
  std::string labels, out;
  std::vector<std::string> transforms;
  std::vector<int> strengths;
  int per_class = 2, threads = 2;
  std::uint64_t seed = 1;
};

// A CSV field, quoted when it needs to be.
std::string csv(const std::string& field) {
  if (field.find_first_of(",\"\n") == std::string::npos) return field;
  std::string q = "\"";
  for (char c : field) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

const bool registered = argtool::register_command(
    "perturb",
    "transformed copies of a labelled set (holes, noise, resampling, cuts, scale; strengths "
    "1-5) for eval --queries; seeded, so the same seed writes the same bytes",
    [](CLI::App& app) {
      auto a = std::make_shared<PerturbArgs>();
      app.add_option("--labels", a->labels, "CSV with header model_id,path,class")
          ->required()
          ->check(CLI::ExistingFile);
      app.add_option("--out", a->out, "folder to write into: one folder per transform and strength")
          ->required();
      std::vector<std::string> names;
      for (auto k : arg::all_perturbations()) names.push_back(arg::perturbation_name(k));
      app.add_option("--transform", a->transforms, "only these transforms (repeatable)")
          ->check(CLI::IsMember(names));
      app.add_option("--strength", a->strengths, "only these strengths (repeatable; 1-5)")
          ->check(CLI::Range(1, 5));
      app.add_option("--per-class", a->per_class,
                     "models of each class to transform (the first ones in the file; 0 = all)")
          ->check(CLI::Range(0, 100000));
      app.add_option("--seed", a->seed, "seed of every random choice");
      app.add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 256));
      return [a] {
        const arg::LabelSet set = arg::parse_label_csv(argtool::read_file_bytes(a->labels));
        const fs::path root = fs::path(a->labels).parent_path();
        std::vector<arg::Perturbation> kinds;
        for (const auto& t : a->transforms) kinds.push_back(*arg::parse_perturbation(t));
        if (kinds.empty()) kinds = arg::all_perturbations();
        if (a->strengths.empty()) a->strengths = {1, 2, 3, 4, 5};
        // The models to transform: the first per_class of each class, in file order.
        std::vector<std::size_t> chosen;
        std::vector<int> taken(set.classes.size(), 0);
        for (std::size_t i = 0; i < set.models.size(); ++i)
          if (a->per_class == 0 || taken[std::size_t(set.class_of[i])]++ < a->per_class)
            chosen.push_back(i);
        // Queries for the baseline: the chosen models as they are.
        fs::create_directories(fs::path(a->out) / "clean");
        std::string clean = "model_id,path,class\n";
        for (std::size_t i : chosen)
          clean += csv(set.models[i].id) + "," +
                   csv(fs::absolute(root / set.models[i].path).lexically_normal().string()) + "," +
                   csv(set.models[i].label) + "\n";
        argtool::write_file_bytes((fs::path(a->out) / "clean" / "labels.csv").string(), clean);
        std::vector<arg::Mesh> meshes(chosen.size());
        argtool::run_with_progress("read", chosen.size(), a->threads, [&](std::size_t k) {
          meshes[k] = arg::read_mesh(
              argtool::read_file_bytes((root / set.models[chosen[k]].path).string()));
        });
        for (arg::Perturbation kind : kinds)
          for (int s : a->strengths) {
            const std::string name =
                std::string(arg::perturbation_name(kind)) + "_" + std::to_string(s);
            const fs::path dir = fs::path(a->out) / name;
            fs::create_directories(dir);
            std::vector<std::string> lines(chosen.size());
            argtool::run_with_progress(name, chosen.size(), a->threads, [&](std::size_t k) {
              const arg::LabelledModel& m = set.models[chosen[k]];
              const std::uint64_t seed = arg::gen::mix_seed(m.id, a->seed);
              const arg::Mesh out = arg::perturb(meshes[k], kind, s, seed);
              const std::string file = "m" + std::to_string(chosen[k]) + ".ply";
              argtool::write_file_bytes((dir / file).string(), arg::write_ply_binary(out));
              lines[k] = csv(m.id + "/" + name) + "," + file + "," + csv(m.label) + "\n";
            });
            std::string labels = "model_id,path,class\n";
            for (const auto& l : lines) labels += l;
            argtool::write_file_bytes((dir / "labels.csv").string(), labels);
          }
        std::printf("wrote %zu transforms x %zu strengths of %zu models under %s\n", kinds.size(),
                    a->strengths.size(), chosen.size(), a->out.c_str());
        return 0;
      };
    });

}  // namespace
