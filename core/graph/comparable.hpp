// Which ARGs may be compared, and which a newer builder would make differently.
#pragma once

#include <cstdint>
#include <string>

#include "graph/arg_graph.hpp"

namespace arg {

// Builder versions read like semantic versions: a new major or minor version changes what the
// measures mean or how they are taken (builder 1.1 fills holes and measures curvature on a copy
// smoothed by 80 Taubin steps, where 1.0 kept holes and took the mesh as given), so the same
// mesh gives other values and SIM between builds of two minor versions ranks by the difference
// of builders as much as of shapes. A patch changes no value's meaning. Comparable: the same
// major and minor version and the same build options (format_build_options of both equal);
// patch versions may differ.
bool comparable(const ArgGraph& a, const ArgGraph& b);

// Empty when comparable; otherwise a sentence naming both builder versions and both options.
std::string incomparable_reason(const ArgGraph& a, const ArgGraph& b);

// Throws Incomparable with incomparable_reason when a and b are not comparable.
void require_comparable(const ArgGraph& a, const ArgGraph& b);

// True when this build of the core would make `g` differently: it was written in an older
// binary format, or by a builder of another major or minor version.
bool rebuild_needed(const ArgGraph& g);

// "1.1.0" of 10100.
std::string builder_version_text(std::uint32_t version);

}  // namespace arg
