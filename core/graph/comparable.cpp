// The comparability rule of ARGs (see comparable.hpp).
#include "graph/comparable.hpp"

#include "common/errors.hpp"
#include "graph/serialize.hpp"

namespace arg {

namespace {

// major * 100 + minor: what must be equal for two builds to compare.
std::uint32_t major_minor(std::uint32_t version) {
  return version / 100;
}

std::string described(const ArgGraph& g) {
  return "builder " + builder_version_text(g.builder_version) + " with options '" +
         format_build_options(g.options) + "'";
}

// Field by field rather than by format_build_options' text: this runs on every row of a ranking.
// The fields are those that text holds (threads never changes a result).
bool same_options(const BuildOptions& a, const BuildOptions& b) {
  return a.levels == b.levels && a.mu == b.mu && a.base_points == b.base_points &&
         a.surface == b.surface && a.proxy_resolution == b.proxy_resolution && a.holes == b.holes;
}

}  // namespace

bool comparable(const ArgGraph& a, const ArgGraph& b) {
  return major_minor(a.builder_version) == major_minor(b.builder_version) &&
         same_options(a.options, b.options);
}

std::string incomparable_reason(const ArgGraph& a, const ArgGraph& b) {
  if (comparable(a, b)) return {};
  return "the first ARG was made by " + described(a) + ", the second by " + described(b);
}

void require_comparable(const ArgGraph& a, const ArgGraph& b) {
  if (!comparable(a, b)) throw Incomparable(incomparable_reason(a, b));
}

bool rebuild_needed(const ArgGraph& g) {
  return g.format < kFormatVersion ||
         major_minor(g.builder_version) != major_minor(current_builder_version());
}

std::string builder_version_text(std::uint32_t version) {
  return std::to_string(version / 10000) + "." + std::to_string(version / 100 % 100) + "." +
         std::to_string(version % 100);
}

}  // namespace arg
