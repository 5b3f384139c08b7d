// libFuzzer target: valid ARGs with fuzz-chosen bytes overwritten and the digest resealed.
//
// Random bytes never get past the digest check of deserialize_arg, so this target starts from a
// real ARG (built from a small generated model), applies the fuzz input as patches, reseals the
// digest and checks that the structural validation rejects (with InputError) or accepts
// consistently; whatever it accepts must serialise back unchanged and be safe to match, and so
// must what it accepts without the value checks (deserialize_arg with check_digest false), and
// a ranking's row reader must agree with it (check_packed_reader).
//
// Input: byte 0 picks the base graph (bit 6: one without colour, which a ranking reads as a row
// straight into its keys); then patches of [offset: u16 LE][length: u8][bytes]. With
// bit 7 of byte 0 set, the declared total size is refreshed after patching, so patches that
// change counts can be combined with an input whose tail (after the last patch) resizes the value
// to a multiple of 4 bytes: the last two bytes, as a signed 16-bit LE word count to add.
#include <algorithm>
#include <vector>

#include "fuzz_support.hpp"
#include "gen/generate_models.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"

namespace arg::fuzz {

// A few small real graphs: different classes, levels and topology; with colour, then without.
inline const std::vector<std::string>& base_graphs() {
  static const std::vector<std::string> bases = [] {
    struct Spec {
      const char* label;
      int levels;
    };
    std::vector<std::string> out;
    for (bool colour : {true, false})
      for (const Spec& spec :
           {Spec{"torus", 3}, Spec{"fourleg", 4}, Spec{"cup", 2}, Spec{"octopus", 5}}) {
        BuildOptions options;
        options.levels = spec.levels;
        options.base_points = 16;
        out.push_back(
            serialize_arg(build_arg(generate_model(spec.label, 0, 10, colour).mesh, options)));
      }
    return out;
  }();
  return bases;
}

inline void put_u32(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + std::size_t(i)] = char((value >> (8 * i)) & 0xff);
}

inline int fuzz_arg_structure(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::vector<std::string>& bases = base_graphs();
  // Bits 0-5 pick the model, bit 6 the model without colour (4 to 7).
  const std::size_t pick = (data[0] & 0x3f) % 4 + ((data[0] & 0x40) ? 4 : 0);
  const std::string& base = bases[pick];
  const bool refresh_size = (data[0] & 0x80) != 0;
  std::string bytes = base;
  std::size_t at = 1;
  while (at + 3 <= size) {
    const std::size_t offset = std::size_t(data[at]) | std::size_t(data[at + 1]) << 8;
    std::size_t length = data[at + 2];
    at += 3;
    length = std::min(length, size - at);
    if (length == 0) break;
    for (std::size_t k = 0; k < length; ++k) {
      const std::size_t target = (offset + k) % bytes.size();
      if (target < 16 || target >= 24) bytes[target] = char(data[at + k]);  // not the digest
    }
    at += length;
  }
  if (refresh_size) {
    if (size >= 3) {
      const int words = std::int16_t(std::uint16_t(data[size - 2] | data[size - 1] << 8));
      const long long target = (long long)bytes.size() + 4LL * words;
      if (target >= 24 && target <= (long long)(4 * base.size()))
        bytes.resize(std::size_t(target), '\0');
    }
    put_u32(bytes, 8, std::uint32_t(bytes.size()));
  }
  try {
    reseal_arg_digest(bytes);
    const ArgGraph graph = deserialize_arg(bytes);
    ARG_FUZZ_CHECK(serialize_arg(graph) == bytes);
    // Whatever the reader accepts, the matcher must take: SIM in [0, 1], symmetric, 0 on itself.
    const ArgGraph other = deserialize_arg(base);
    const double forth = arg_similarity(graph, other), back = arg_similarity(other, graph);
    ARG_FUZZ_CHECK(forth >= 0.0 && forth <= 1.0);
    ARG_FUZZ_CHECK(forth == back);
    ARG_FUZZ_CHECK(arg_similarity(graph, graph) == 0.0);
    // The finest level: its sub-graphs have no children at all (an empty section).
    for (const PartMatch& m : part_match(graph, graph.levels(), 0, other))
      ARG_FUZZ_CHECK(m.score >= 0.0 && m.score <= 1.0);
  } catch (const Error&) {
  }
  // Read back as a stored value (no digest, no value checks): sound structure with any node
  // values, NaN included, must still be safe to match (results unchecked).
  try {
    const ArgGraph graph = deserialize_arg(bytes, /*check_digest=*/false);
    exercise_matching(graph, deserialize_arg(base));
  } catch (const Error&) {
  }
  check_packed_reader(bytes, deserialize_arg(bases[(pick + 1) % bases.size()]));
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_arg_structure)
