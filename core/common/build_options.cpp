// Parsing and printing the options of an ARG build.
#include "common/build_options.hpp"

#include <iterator>

#include "common/errors.hpp"
#include "common/key_values.hpp"

namespace arg {

namespace {

constexpr const char* kWhat = "build options";
constexpr const char* kMuNames[] = {"geodesic", "height", "centroid"};  // in MuKind's order
constexpr const char* kSurfaceNames[] = {"auto", "mesh", "proxy"};      // in SurfaceKind's order
constexpr const char* kHoleNames[] = {"keep", "fill"};                  // in HoleKind's order

// A key: a number in [lo, hi] kept in `number`, or a choice of `words` that `choose` applies.
struct Option {
  const char* name;
  int BuildOptions::*number;
  long lo, hi;
  const char* const* words;
  int word_count;
  void (*choose)(BuildOptions&, int);
};
constexpr Option kOptions[] = {
    {"levels", &BuildOptions::levels, kMinLevels, kMaxLevels, nullptr, 0, nullptr},
    {"mu", nullptr, 0, 0, kMuNames, int(std::size(kMuNames)),
     [](BuildOptions& o, int i) { o.mu = MuKind(i); }},
    {"base_points", &BuildOptions::base_points, kMinBasePoints, kMaxBasePoints, nullptr, 0,
     nullptr},
    {"surface", nullptr, 0, 0, kSurfaceNames, int(std::size(kSurfaceNames)),
     [](BuildOptions& o, int i) { o.surface = SurfaceKind(i); }},
    {"proxy_resolution", &BuildOptions::proxy_resolution, kMinProxyResolution, kMaxProxyResolution,
     nullptr, 0, nullptr},
    {"holes", nullptr, 0, 0, kHoleNames, int(std::size(kHoleNames)),
     [](BuildOptions& o, int i) { o.holes = HoleKind(i); }},
    {"threads", &BuildOptions::threads, 1, kMaxThreads, nullptr, 0, nullptr},
};

// "a, b or c"
std::string either(const char* const* words, int count) {
  std::string out;
  for (int i = 0; i < count; ++i)
    out += std::string(i == 0 ? "" : i + 1 == count ? " or " : ", ") + words[i];
  return out;
}

// The name of choice i of `names`, or of choice `fallback` for a value out of range.
template <std::size_t N>
const char* name_in(const char* const (&names)[N], int i, int fallback) {
  return i >= 0 && i < int(N) ? names[i] : names[fallback];
}

}  // namespace

const char* mu_kind_name(MuKind kind) {
  return name_in(kMuNames, int(kind), 0);
}

const char* surface_kind_name(SurfaceKind kind) {
  return name_in(kSurfaceNames, int(kind), 0);
}

const char* hole_kind_name(HoleKind kind) {
  return name_in(kHoleNames, int(kind), 1);
}

const std::vector<BuildOptionKey>& build_option_keys() {
  static const std::vector<BuildOptionKey> keys = [] {
    std::vector<BuildOptionKey> k;
    for (const Option& o : kOptions)
      k.push_back({o.name, o.lo, o.hi, {o.words, o.words + o.word_count}});
    return k;
  }();
  return keys;
}

BuildOptions parse_build_options(std::string_view text) {
  BuildOptions options;
  for (const auto& [key, value] : split_key_values(text, kWhat)) {
    const Option* option = nullptr;
    for (const Option& o : kOptions)
      if (key == o.name) option = &o;
    if (!option) {
      const char* names[std::size(kOptions)];
      for (std::size_t i = 0; i < std::size(kOptions); ++i) names[i] = kOptions[i].name;
      throw InputError("build options: unknown key \"" + key + "\" (expected " +
                       either(names, int(std::size(kOptions))) + ")");
    }
    if (option->number) {
      options.*option->number = int(parse_integer(value, key, kWhat, option->lo, option->hi));
      continue;
    }
    int chosen = -1;
    for (int i = 0; i < option->word_count; ++i)
      if (value == option->words[i]) chosen = i;
    if (chosen < 0)
      throw InputError("build options: " + key + "=" + value + " (expected " +
                       either(option->words, option->word_count) + ")");
    option->choose(options, chosen);
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
