// Parsing and printing the options of an ARG build.
#include "pipeline/build_options.hpp"

#include "common/errors.hpp"
#include "common/key_values.hpp"

namespace arg {

const char* mu_kind_name(MuKind kind) {
  switch (kind) {
    case MuKind::Geodesic:
      return "geodesic";
    case MuKind::Height:
      return "height";
    case MuKind::Centroid:
      return "centroid";
  }
  return "geodesic";
}

const char* surface_kind_name(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::Auto:
      return "auto";
    case SurfaceKind::Mesh:
      return "mesh";
    case SurfaceKind::Proxy:
      return "proxy";
  }
  return "auto";
}

const char* hole_kind_name(HoleKind kind) {
  return kind == HoleKind::Keep ? "keep" : "fill";
}

BuildOptions parse_build_options(std::string_view text) {
  static const char* what = "build options";
  BuildOptions options;
  for (const auto& [key, value] : split_key_values(text, what)) {
    if (key == "levels") {
      options.levels = int(parse_integer(value, key, what, 1, kMaxLevels));
    } else if (key == "mu") {
      if (value == "geodesic")
        options.mu = MuKind::Geodesic;
      else if (value == "height")
        options.mu = MuKind::Height;
      else if (value == "centroid")
        options.mu = MuKind::Centroid;
      else
        throw InputError("build options: mu=" + value + " (expected geodesic, height or centroid)");
    } else if (key == "base_points") {
      options.base_points = int(parse_integer(value, key, what, 8, 4096));
    } else if (key == "surface") {
      if (value == "auto")
        options.surface = SurfaceKind::Auto;
      else if (value == "mesh")
        options.surface = SurfaceKind::Mesh;
      else if (value == "proxy")
        options.surface = SurfaceKind::Proxy;
      else
        throw InputError("build options: surface=" + value + " (expected auto, mesh or proxy)");
    } else if (key == "proxy_resolution") {
      options.proxy_resolution = int(parse_integer(value, key, what, 16, 256));
    } else if (key == "holes") {
      if (value == "fill")
        options.holes = HoleKind::Fill;
      else if (value == "keep")
        options.holes = HoleKind::Keep;
      else
        throw InputError("build options: holes=" + value + " (expected fill or keep)");
    } else if (key == "threads") {
      options.threads = int(parse_integer(value, key, what, 1, 256));
    } else {
      throw InputError(
          "build options: unknown key \"" + key +
          "\" (expected levels, mu, base_points, surface, proxy_resolution, holes or threads)");
    }
  }
  return options;
}

std::string format_build_options(const BuildOptions& options) {
  return "levels=" + std::to_string(options.levels) + " mu=" + mu_kind_name(options.mu) +
         " base_points=" + std::to_string(options.base_points) +
         " surface=" + surface_kind_name(options.surface) +
         " proxy_resolution=" + std::to_string(options.proxy_resolution) +
         " holes=" + hole_kind_name(options.holes);
}

}  // namespace arg
