// argtool scale-gen: a large catalogue of ARGs for the scale benchmarks, as rows for COPY.
//
// Builds outside the database, on several threads, what a museum network would load: one row
// per model, "id <TAB> museum <TAB> period <TAB> class <TAB> arg" in COPY's text format (the
// arg in its text form, arg1: and base64), in id order whatever the thread count. Models come
// from the generator (the 9 classes in turn, each variant turned, scaled and jittered by
// perturb_mesh) or, with --labels, from a labelled set such as SHREC 2007, or, with
// --jitter-from, as jittered copies of the values of earlier rows (eval/value_jitter.hpp: a
// million rows in minutes, for the index benchmarks). Museum (M1..M<n>)
// and period are drawn per row from a stream seeded by --seed and the id, so a filter such as
// museum = 'M7' keeps about 1/n of the rows. The same arguments give the same bytes.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "command_registry.hpp"
#include "common/parallel_for.hpp"
#include "eval/label_file.hpp"
#include "eval/value_jitter.hpp"
#include "eval_models.hpp"
#include "gen/generate_models.hpp"
#include "gen/perturb_mesh.hpp"
#include "gen/seeded_random.hpp"
#include "graph/serialize.hpp"
#include "load_arg.hpp"
#include "pipeline/build_arg.hpp"

namespace {

namespace fs = std::filesystem;

struct ScaleArgs {
  std::string out;
  std::string labels;       // a labelled set instead of generated models
  std::string cache;        // ARG cache folder for --labels (shared with argtool eval)
  std::string jitter_from;  // COPY rows whose values are copied with jitter instead
  double value_jitter = 0.05;
  long long count = 1000;
  long long first_id = 1;
  int resolution = 16;
  double noise = 0.1;
  std::uint64_t seed = 1;
  int museums = 20;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  arg::BuildOptions options;
};

const std::vector<const char*> kPeriods = {
    "Bronze Age", "Archaic",     "Classical", "Hellenistic", "Roman",  "Han dynasty",
    "Medieval",   "Renaissance", "Baroque",   "Georgian",    "Modern", "Contemporary"};

// Museum and period of row `id`, from their own stream so they never depend on the geometry.
std::string metadata(const ScaleArgs& a, long long id) {
  arg::SeededRandom rng(
      arg::gen::mix_seed("scale-gen:metadata", a.seed * 1000003ULL + std::uint64_t(id)));
  const int museum = 1 + rng.below(a.museums);
  const char* period = kPeriods[std::size_t(rng.below(int(kPeriods.size())))];
  return std::to_string(id) + "\tM" + std::to_string(museum) + '\t' + period + '\t';
}

// One COPY row (with its newline) of generated model number `i` (0-based).
std::string generated_row(const ScaleArgs& a, const std::vector<std::string>& classes,
                          long long i) {
  const std::string& label = classes[std::size_t(i) % classes.size()];
  const int variant = int(i / (long long)classes.size());
  arg::GeneratedModel model = arg::generate_model(label, variant, a.resolution, true);
  const arg::Mesh mesh = arg::perturb_mesh(
      model.mesh, arg::gen::mix_seed("scale-gen:perturb", a.seed * 1000003ULL + std::uint64_t(i)),
      a.noise);
  const std::string bytes = arg::serialize_arg(arg::build_arg(mesh, a.options));
  return metadata(a, a.first_id + i) + label + '\t' + arg::arg_to_text(bytes) + '\n';
}

// The class and value of each row of a file written by scale-gen.
struct PoolRow {
  std::string label;
  arg::ArgGraph graph;
};
std::vector<PoolRow> read_pool(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<PoolRow> pool;
  std::string line;
  while (std::getline(in, line)) {
    // id, museum, period, class, arg
    std::size_t at = 0;
    for (int field = 0; field < 3; ++field) at = line.find('\t', at) + 1;
    const std::size_t end = line.find('\t', at);
    if (at == 0 || end == std::string::npos)
      throw std::runtime_error(path + ": not scale-gen rows");
    pool.push_back({line.substr(at, end - at),
                    arg::deserialize_arg(arg::arg_from_text(line.substr(end + 1)))});
  }
  if (pool.empty()) throw std::runtime_error(path + " has no rows");
  return pool;
}

// One COPY row of jittered copy number `i` of the pool.
std::string jittered_row(const ScaleArgs& a, const std::vector<PoolRow>& pool, long long i) {
  const PoolRow& original = pool[std::size_t(i) % pool.size()];
  const arg::ArgGraph copy = arg::jittered_copy(
      original.graph,
      arg::gen::mix_seed("scale-gen:jitter", a.seed * 1000003ULL + std::uint64_t(i)),
      a.value_jitter);
  return metadata(a, a.first_id + i) + original.label + '\t' +
         arg::arg_to_text(arg::serialize_arg(copy)) + '\n';
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int run_scale_gen(ScaleArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<std::string> classes = arg::generator_classes();
  arg::LabelSet set;
  fs::path root;
  if (!a.labels.empty()) {
    set = arg::parse_label_csv(argtool::read_file_bytes(a.labels));
    root = fs::path(a.labels).parent_path();
    a.count = (long long)set.models.size();
    if (!a.cache.empty()) fs::create_directories(a.cache);
  }
  a.options.threads = 1;  // parallel over models instead
  std::vector<PoolRow> pool;
  if (!a.jitter_from.empty()) pool = read_pool(a.jitter_from);

  std::ofstream file;
  std::ostream* out = &std::cout;
  if (a.out != "-") {
    if (fs::path(a.out).has_parent_path()) fs::create_directories(fs::path(a.out).parent_path());
    file.open(a.out, std::ios::binary | std::ios::trunc);
    if (!file) throw std::runtime_error("cannot write " + a.out);
    out = &file;
  }

  // Chunks of rows built in parallel, written in id order.
  const long long chunk = 256;
  std::vector<std::string> rows;
  std::size_t bytes_out = 0, failed = 0;
  for (long long begin = 0; begin < a.count; begin += chunk) {
    const long long end = std::min(a.count, begin + chunk);
    rows.assign(std::size_t(end - begin), std::string());
    std::vector<std::string> errors(rows.size());
    // A model that fails is reported and skipped: its error goes to its slot, not up.
    arg::parallel_for(rows.size(), a.threads, [&](std::size_t k) {
      const long long i = begin + (long long)k;
      try {
        if (!pool.empty()) {
          rows[k] = jittered_row(a, pool, i);
        } else if (a.labels.empty()) {
          rows[k] = generated_row(a, classes, i);
        } else {
          const arg::LabelledModel& m = set.models[std::size_t(i)];
          argtool::Model model;
          argtool::prepare_model(model, (root / m.path).string(), a.options, a.cache, true);
          if (!model.error.empty()) throw std::runtime_error(model.error);
          // A numeric model_id is the row's id; others (SHREC 2011's T0 ...) get their row number.
          const bool numeric =
              !m.id.empty() && m.id.find_first_not_of("0123456789") == std::string::npos;
          rows[k] = metadata(a, numeric ? std::stoll(m.id) : a.first_id + i) + m.label + '\t' +
                    arg::arg_to_text(arg::serialize_arg(model.graph)) + '\n';
        }
      } catch (const std::exception& e) {
        errors[k] = e.what();
      }
    });
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (!errors[k].empty()) {
        std::fprintf(stderr, "\nmodel %lld skipped: %s\n", begin + (long long)k, errors[k].c_str());
        ++failed;
        continue;
      }
      out->write(rows[k].data(), std::streamsize(rows[k].size()));
      bytes_out += rows[k].size();
    }
    if (!*out) throw std::runtime_error("write failed: " + a.out);
    std::fprintf(stderr, "\rscale-gen %lld/%lld models, %.0f MB, %.1f s", end, a.count,
                 double(bytes_out) / 1e6, seconds_since(t0));
  }
  out->flush();
  const double s = seconds_since(t0);
  std::fprintf(
      stderr,
      "\nscale-gen: %lld rows (%zu skipped) in %.1f s: %.1f models/s, %.0f bytes of "
      "text per row\n",
      a.count - (long long)failed, failed, s, double(a.count) / s,
      a.count > (long long)failed ? double(bytes_out) / double(a.count - (long long)failed) : 0.0);
  return failed == 0 ? 0 : 1;
}

const bool registered = argtool::register_command(
    "scale-gen",
    "build many ARGs (generated, or a labelled set) into COPY rows: id, museum, period, class, "
    "arg",
    [](CLI::App& app) {
      auto a = std::make_shared<ScaleArgs>();
      app.add_option("--out", a->out, "file to write the COPY text rows to (- for stdout)")
          ->required();
      app.add_option("--count", a->count, "generated models (the 9 classes in turn)")
          ->check(CLI::Range(0LL, 100000000LL))
          ->capture_default_str();
      app.add_option("--first-id", a->first_id, "id of the first generated row")
          ->capture_default_str();
      app.add_option("--labels", a->labels,
                     "CSV with header model_id,path,class: build these meshes instead (ids are "
                     "their model_id)")
          ->check(CLI::ExistingFile);
      app.add_option("--cache", a->cache, "with --labels: folder caching built ARGs");
      app.add_option("--jitter-from", a->jitter_from,
                     "rows written by scale-gen: make --count jittered copies of their values "
                     "(in turn) instead of building models")
          ->check(CLI::ExistingFile);
      app.add_option("--value-jitter", a->value_jitter,
                     "with --jitter-from: relative amount each stored number moves by")
          ->check(CLI::Range(0.0, 0.5))
          ->capture_default_str();
      app.add_option("--resolution", a->resolution, "grid cells along each model's longest side")
          ->check(CLI::Range(8, 1024))
          ->capture_default_str();
      app.add_option("--noise", a->noise, "vertex jitter, in mean edge lengths")
          ->check(CLI::Range(0.0, 0.45))
          ->capture_default_str();
      app.add_option("--seed", a->seed, "seed of the rotations, noise and metadata")
          ->capture_default_str();
      app.add_option("--museums", a->museums, "museums M1..Mn the rows are spread over")
          ->check(CLI::Range(1, 100000))
          ->capture_default_str();
      app.add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 256));
      argtool::add_build_flags(app, a->options, false);
      return [a] { return run_scale_gen(*a); };
    });

}  // namespace
