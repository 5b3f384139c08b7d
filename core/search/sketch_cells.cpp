// Cells of an inverted-file index over sketches (k-means++ seeded centres, nearest-centre
// filing, probing).
#include "search/sketch_cells.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "common/random.hpp"

namespace arg {

std::vector<std::size_t> choose_cell_centres(const ShapeSketch* sample, std::size_t size,
                                             std::size_t count, std::uint64_t seed,
                                             const StopRequested& stop) {
  std::vector<std::size_t> centres;
  if (size == 0 || count == 0) return centres;
  SeededRandom random(seed);
  centres.push_back(std::size_t(random.bits() % size));
  // nearest[s]: squared distance of sample s to its nearest centre so far.
  std::vector<double> nearest(size, 0);
  for (std::size_t s = 0; s < size; ++s) {
    const double d = sketch_distance(sample[s], sample[centres[0]]);
    nearest[s] = d * d;
  }
  while (centres.size() < count) {
    check_interrupt(stop);
    const double total = std::accumulate(nearest.begin(), nearest.end(), 0.0);
    if (!(total > 0)) break;  // every sample lies on a centre
    const double target = random.unit() * total;
    double sum = 0;
    std::size_t pick = size;
    for (std::size_t s = 0; s < size; ++s) {
      if (nearest[s] <= 0) continue;
      sum += nearest[s];
      pick = s;  // the last positive one when rounding leaves target above every sum
      if (sum > target) break;
    }
    centres.push_back(pick);
    for (std::size_t s = 0; s < size; ++s) {
      const double d = sketch_distance(sample[s], sample[pick]);
      nearest[s] = std::min(nearest[s], d * d);
    }
  }
  return centres;
}

std::size_t default_candidates(double rows) {
  const double decades = rows > 1 ? std::log10(rows) - 4 : 0;
  return 25 * std::size_t(std::max(1.0, std::floor(decades + 0.5)));
}

std::vector<CoarseQuery> coarse_centres(const ShapeSketch* centres, std::size_t count) {
  std::vector<CoarseQuery> out(count);
  for (std::size_t c = 0; c < count; ++c) out[c] = coarse_query(centres[c]);
  return out;
}

namespace {

// Every centre by the coarse distance, nearest first (ties by index), the first `refined` of
// them then ordered by the sketch distance.
std::vector<std::pair<double, std::size_t>> ranked_centres(const ShapeSketch& sketch,
                                                           const ShapeSketch* centres,
                                                           std::size_t count, std::size_t refined,
                                                           std::size_t keep,
                                                           const CoarseQuery* coarse) {
  std::vector<std::pair<double, std::size_t>> by_distance(count);
  if (coarse && count > kCellsRefined) {
    const CoarseQuery q = coarse_query(sketch);
    for (std::size_t c = 0; c < count; ++c) by_distance[c] = {coarse_distance(q, coarse[c]), c};
    refined = std::min(refined, count);
    keep = std::max(keep, refined);
    std::partial_sort(by_distance.begin(), by_distance.begin() + std::ptrdiff_t(keep),
                      by_distance.end());
    for (std::size_t k = 0; k < refined; ++k)
      by_distance[k].first = sketch_distance(sketch, centres[by_distance[k].second]);
    std::sort(by_distance.begin(), by_distance.begin() + std::ptrdiff_t(refined));
  } else {
    for (std::size_t c = 0; c < count; ++c)
      by_distance[c] = {sketch_distance(sketch, centres[c]), c};
    std::partial_sort(by_distance.begin(), by_distance.begin() + std::ptrdiff_t(keep),
                      by_distance.end());
  }
  return by_distance;
}

}  // namespace

std::size_t nearest_cell(const ShapeSketch& sketch, const ShapeSketch* centres, std::size_t count,
                         const CoarseQuery* coarse) {
  return ranked_centres(sketch, centres, count, kCellsRefined, 1, coarse)[0].second;
}

std::vector<std::size_t> cells_to_probe(const ShapeSketch& query, const ShapeSketch* centres,
                                        std::size_t count, std::size_t probes,
                                        const CoarseQuery* coarse) {
  const std::size_t keep = std::min(probes, count);
  const std::vector<std::pair<double, std::size_t>> by_distance =
      ranked_centres(query, centres, count, kCellsRefined, keep, coarse);
  std::vector<std::size_t> cells(keep);
  for (std::size_t k = 0; k < keep; ++k) cells[k] = by_distance[k].second;
  return cells;
}

}  // namespace arg
