// argtool gen: writes the generated sample catalogue (meshes, catalogue.csv, labels.csv).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "command_registry.hpp"
#include "gen/generate_models.hpp"
#include "gen/seeded_random.hpp"
#include "io/write_mesh.hpp"

namespace {

struct GenArgs {
  std::string out;
  int per_class = 5;
  int resolution = 48;
  std::string format = "off";
  std::vector<std::string> classes;
  bool labels = false;
  bool no_colour = false;
};

// Invented but plausible museum records: each class has a few (period, material) pairs that
// belong together, so no record reads "Archaic porcelain".
struct Provenance {
  const char* period;
  const char* material;
};

const std::vector<std::vector<Provenance>>& provenances() {
  static const std::vector<std::vector<Provenance>> table = {
      // vase
      {{"Archaic", "terracotta"},
       {"Classical", "terracotta"},
       {"Song dynasty", "celadon stoneware"},
       {"Ming dynasty", "porcelain"},
       {"Modern", "glazed earthenware"}},
      // cup
      {{"Classical", "terracotta"},
       {"Roman", "glass"},
       {"Georgian", "porcelain"},
       {"Art Deco", "silver"},
       {"Modern", "stoneware"}},
      // amphora
      {{"Archaic", "terracotta"},
       {"Classical", "painted terracotta"},
       {"Hellenistic", "terracotta"},
       {"Roman", "coarse clay"}},
      // torus
      {{"Bronze Age", "bronze"}, {"Roman", "gold"}, {"Han dynasty", "jade"}, {"Modern", "marble"}},
      // fourleg
      {{"Archaic", "bronze"},
       {"Han dynasty", "terracotta"},
       {"Roman", "marble"},
       {"Modern", "carved oak"}},
      // human
      {{"Archaic", "limestone"},
       {"Classical", "marble"},
       {"Renaissance", "bronze"},
       {"Modern", "plaster"}},
      // table
      {{"Renaissance", "walnut"},
       {"Baroque", "oak"},
       {"Victorian", "mahogany"},
       {"Modern", "pine"}},
      // chair
      {{"Baroque", "walnut"}, {"Georgian", "mahogany"}, {"Victorian", "oak"}, {"Modern", "beech"}},
      // octopus
      {{"Minoan", "painted terracotta"},
       {"Hellenistic", "bronze"},
       {"Edo period", "lacquered wood"},
       {"Modern", "glass"}},
  };
  return table;
}

const std::vector<const char*> kWorkshops = {"Workshop of the Lantern Painter",
                                             "Atelier Halvorsen",
                                             "Kallias and Sons",
                                             "Studio Meridian",
                                             "The Brackwater Guild",
                                             "Maison Orlandi",
                                             "Tessaly Vale Workshop",
                                             "Anonymous workshop"};

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char c : s) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string mesh_bytes(const arg::Mesh& mesh, const std::string& format) {
  if (format == "ply") return arg::write_ply_binary(mesh);
  if (format == "stl") return arg::write_stl_binary(mesh);
  if (format == "obj") return arg::write_obj(mesh);
  return arg::write_off(mesh);
}

std::string capitalised(std::string s) {
  if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
  return s;
}

int run_gen(const GenArgs& a) {
  namespace fs = std::filesystem;
  fs::create_directories(a.out);
  const std::vector<std::string> all = arg::generator_classes();
  const std::vector<std::string>& wanted = a.classes.empty() ? all : a.classes;

  // The generator builds every model +z up: the catalogue says so (tools/demo/load.sql keeps it
  // for the pictures' up).
  std::string catalogue =
      "model_id,path,class,inventory_no,title,artist,period,material,licence,up\n";
  std::string labels = "model_id,path,class\n";
  std::size_t triangles = 0;
  int written = 0;
  for (std::size_t c = 0; c < all.size(); ++c) {
    const std::string& label = all[c];
    if (std::find(wanted.begin(), wanted.end(), label) == wanted.end()) continue;
    const std::vector<Provenance>& choices = provenances()[c];
    for (int v = 0; v < a.per_class; ++v) {
      const arg::GeneratedModel model = arg::generate_model(label, v, a.resolution, !a.no_colour);
      const std::string path = model.name + "." + a.format;
      argtool::write_file_bytes((fs::path(a.out) / path).string(),
                                mesh_bytes(model.mesh, a.format));
      triangles += static_cast<std::size_t>(model.mesh.F.rows());
      ++written;

      // Metadata from its own stream, so it never shifts when the geometry's draws change; the
      // inventory number depends on class and variant only, not on which classes were asked for.
      arg::gen::SeededRandom rng(
          arg::gen::mix_seed("catalogue:" + label, static_cast<unsigned>(v)));
      char inventory[32];
      std::snprintf(inventory, sizeof inventory, "GEN-2026-%04d",
                    static_cast<int>((c + 1) * 1000 + static_cast<std::size_t>(v)));
      const std::string title =
          capitalised(model.description) + " (variant " + std::to_string(v) + ")";
      const char* artist = kWorkshops[rng.below(static_cast<int>(kWorkshops.size()))];
      const Provenance& provenance = choices[rng.below(static_cast<int>(choices.size()))];
      catalogue += csv_field(model.name) + ',' + csv_field(path) + ',' + csv_field(label) + ',' +
                   inventory + ',' + csv_field(title) + ',' + csv_field(artist) + ',' +
                   csv_field(provenance.period) + ',' + csv_field(provenance.material) +
                   ",CC0 (generated),+z\n";
      labels += csv_field(model.name) + ',' + csv_field(path) + ',' + csv_field(label) + '\n';
    }
  }
  argtool::write_file_bytes((fs::path(a.out) / "catalogue.csv").string(), catalogue);
  if (a.labels) argtool::write_file_bytes((fs::path(a.out) / "labels.csv").string(), labels);
  std::cout << "wrote " << written << " models (" << triangles << " triangles) and catalogue.csv"
            << (a.labels ? " and labels.csv" : "") << " to " << a.out << "\n";
  return 0;
}

const bool registered = argtool::register_command(
    "gen", "write the generated sample catalogue: meshes, catalogue.csv, labels.csv",
    [](CLI::App& app) {
      auto a = std::make_shared<GenArgs>();
      app.add_option("--out", a->out, "directory to write into (created if missing)")->required();
      app.add_option("--per-class", a->per_class, "variants per class")
          ->check(CLI::Range(0, 999))
          ->capture_default_str();
      app.add_option("--resolution", a->resolution, "grid cells along each model's longest side")
          ->check(CLI::Range(8, 1024))
          ->capture_default_str();
      app.add_option("--format", a->format, "mesh file format")
          ->check(CLI::IsMember({"off", "ply", "stl", "obj"}))
          ->capture_default_str();
      app.add_option("--class", a->classes, "only these classes (repeatable)")
          ->check(CLI::IsMember(arg::generator_classes()));
      app.add_flag("--labels", a->labels, "also write labels.csv (model_id,path,class)");
      app.add_flag("--no-colour", a->no_colour, "leave the meshes uncoloured");
      return [a] { return run_gen(*a); };
    });

}  // namespace
