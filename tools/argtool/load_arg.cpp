// Reading ARG files and building ARGs from mesh files for the argtool subcommands.
#include "load_arg.hpp"

#include "command_registry.hpp"
#include "common/errors.hpp"
#include "graph/serialize.hpp"

namespace argtool {

LoadedArg load_arg(const std::string& path, const arg::BuildOptions& options,
                   const std::string& texture_path, const arg::Limits& limits) {
  LoadedArg out;
  std::string bytes = read_file_bytes(path);
  if (bytes.compare(0, 4, "ARGR") == 0) {
    out.graph = arg::deserialize_arg(bytes);
    out.bytes = std::move(bytes);
    return out;
  }
  std::string texture = texture_path.empty() ? std::string() : read_file_bytes(texture_path);
  try {
    out.bytes = arg::build_arg_bytes(bytes, texture, options, limits, {}, &out.report);
  } catch (const arg::MemoryLimitError& e) {
    throw arg::MemoryLimitError(path + ": " + e.what());
  } catch (const arg::LimitError& e) {
    throw arg::LimitError(path + ": " + e.what());  // still a limit: argtool exits with 3
  } catch (const arg::Error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  out.graph = arg::deserialize_arg(out.bytes);
  out.built = true;
  return out;
}

void add_build_flags(CLI::App& app, arg::BuildOptions& options, bool with_threads) {
  app.add_option("--levels", options.levels, "finest level n (2^n intervals of mu)")
      ->check(CLI::Range(arg::kMinLevels, arg::kMaxLevels));
  app.add_option_function<std::string>(
         "--mu",
         [&options](const std::string& kind) {
           options = arg::parse_build_options(arg::format_build_options(options) + " mu=" + kind);
         },
         "geodesic (default), height or centroid")
      ->check(CLI::IsMember({"geodesic", "height", "centroid"}));
  app.add_option("--base-points", options.base_points, "base points of the geodesic integral")
      ->check(CLI::Range(arg::kMinBasePoints, arg::kMaxBasePoints));
  app.add_option_function<std::string>(
      "--build-options",
      [&options](const std::string& text) {
        options = arg::parse_build_options(arg::format_build_options(options) + " " + text);
      },
      "further build options as key=value text (surface=proxy proxy_resolution=64 ...)");
  if (!with_threads) return;
  app.add_option("--threads", options.threads, "threads for mu (never changes the result)")
      ->check(CLI::Range(1, arg::kMaxThreads));
}

}  // namespace argtool
