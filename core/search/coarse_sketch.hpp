// A sketch's cheap stand-in: what an index reads of every entry of the cells it probes, to
// choose the few whose whole sketch it then reads.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "search/shape_sketch.hpp"

namespace arg {

// The panorama's lowest frequencies the coarse distance reads: per frame and view, angular
// 0..kCoarseAngular by axial 0..kCoarseAxial. Chosen on the 965 models of the three labelled
// sets: ranking a pool by the coarse distance, then its 200 nearest by the sketch distance,
// keeps SIM's ten nearest among the 50 nearest as often as the sketch alone, less .003
// (docs/BENCHMARKS.md "An index on the arg column").
inline constexpr int kCoarseAngular = 4, kCoarseAxial = 2;
inline constexpr int kCoarsePerView = (kCoarseAngular + 1) * (kCoarseAxial + 1);
inline constexpr int kCoarsePanorama = 2 * 6 * kCoarsePerView;  // two frames of six views

// The query's side, prepared once: its graph blocks, its lowest panorama frequencies and the
// logarithms of its eigenvalues.
struct CoarseQuery {
  std::uint16_t flags = 0;
  bool has_panorama = false, has_spectrum = false, has_colour = false;
  std::array<float, kSketchGraphDims> graph{};
  std::array<float, kCoarsePanorama> panorama{};
  std::array<float, kSpectrumSize> log_spectrum{};
};
CoarseQuery coarse_query(const ShapeSketch& query);

// The sketch distance with the panorama's terms read from its lowest frequencies only (their
// taxicab distance over 6, the better frame) and the eigenvalues' logarithms approximated from
// their bits; weights and the rules for missing terms as sketch_distance's. Reads `bytes` (a
// sketch as written) at fixed places without checking it whole: bytes that are not one give
// +infinity, never a read out of bounds. An order of candidates, not a value to report.
double coarse_sketch_distance(const CoarseQuery& query, std::string_view bytes);

// The same distance between two prepared sides (a row and the cell centres an index files it
// among): both panoramas' lowest frequencies as their sketches hold them.
double coarse_distance(const CoarseQuery& a, const CoarseQuery& b);

}  // namespace arg
