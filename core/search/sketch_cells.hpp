// Cells of an inverted-file index over sketches: centres, filing a sketch, the cells to probe.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/limits.hpp"
#include "search/coarse_sketch.hpp"
#include "search/shape_sketch.hpp"

namespace arg {

// Most cells an index may have (the reloption's bound): a query reads every centre.
inline constexpr std::size_t kMaxSketchCells = 4096;

// Chooses up to `count` centres among the `size` sketches of `sample` (indices into it, distinct,
// in the order chosen) by k-means++ seeding under sketch_distance: the first at random, each next
// one with a chance proportional to its squared distance to the nearest centre chosen so far. The
// distance is not a norm, so there is no mean to move a centre to; a centre is a member, and
// seeding alone spreads the centres over the sample's dense regions. Fewer centres than
// `count` when the sample has fewer distinct sketches (duplicates are never two centres).
// The same sample and seed give the same centres. Polls `stop` once a centre.
std::vector<std::size_t> choose_cell_centres(const ShapeSketch* sample, std::size_t size,
                                             std::size_t count, std::uint64_t seed,
                                             const StopRequested& stop = {});

// Among more centres than this, filing and probing rank them all by the coarse distance
// (coarse_sketch.hpp: about a tenth of the sketch distance's time) and only this many nearest
// by the sketch distance. A million rows make a thousand cells, and filing each row by a
// thousand sketch distances took most of the build (docs/BENCHMARKS.md "A million rows").
inline constexpr std::size_t kCellsRefined = 32;

// The centres' coarse sides, coarse_centres[c] = coarse_query(centres[c]).
std::vector<CoarseQuery> coarse_centres(const ShapeSketch* centres, std::size_t count);

// The cell of `sketch`: the index of its nearest centre by sketch_distance with default
// weights (the lowest index among equals), among the kCellsRefined nearest by the coarse
// distance when `coarse` (the centres' coarse sides) is given. `count` must be at least 1.
std::size_t nearest_cell(const ShapeSketch& sketch, const ShapeSketch* centres, std::size_t count,
                         const CoarseQuery* coarse = nullptr);

// How many candidates a search ranks by SIM when the setting leaves it to the index's size
// (arg.ivf_candidates = 0): 25 a decade of rows past 10,000, at least 25 (rounded at half
// decades: 25 up to about 300,000 rows, 50 up to 3 million, 75 beyond). More rows put more
// near neighbours within the sketch's error of each other: of jittered copies, 25 candidates
// found 1.000 of SIM's ten nearest at 100,000 rows but .967 at a million, where 50 find .993
// (docs/BENCHMARKS.md "A million rows").
std::size_t default_candidates(double rows);

// The `probes` cells nearest to `query` (all `count` of them when probes >= count), nearest
// first, ties by index: the cells a search reads. With `coarse`, the cells are ranked by the
// coarse distance and the first kCellsRefined of them by the sketch distance (the ones a
// search reads first: arg.ivf_probes is at most a few dozen).
std::vector<std::size_t> cells_to_probe(const ShapeSketch& query, const ShapeSketch* centres,
                                        std::size_t count, std::size_t probes,
                                        const CoarseQuery* coarse = nullptr);

}  // namespace arg
