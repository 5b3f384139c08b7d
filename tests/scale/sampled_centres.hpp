// The cell centres an arg_ivf build would choose, for the studies of tests/scale.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

#include "common/random.hpp"
#include "search/sketch_cells.hpp"

namespace study {

// As the build does: a uniform random sample of 20 rows a cell (a fixed seed, so every study
// sees the same one), from which choose_cell_centres picks `cells` centres.
inline std::vector<arg::ShapeSketch> sampled_centres(const std::vector<arg::ShapeSketch>& sketch,
                                                     std::size_t cells) {
  const std::size_t n = sketch.size();
  std::vector<std::size_t> ids(n);
  std::iota(ids.begin(), ids.end(), 0);
  arg::SeededRandom random(1);
  for (std::size_t i = n; i > 1; --i) std::swap(ids[i - 1], ids[random.bits() % i]);
  ids.resize(std::min(n, 20 * cells));
  std::vector<arg::ShapeSketch> sample;
  for (std::size_t id : ids) sample.push_back(sketch[id]);
  std::vector<arg::ShapeSketch> centres;
  for (std::size_t c : arg::choose_cell_centres(sample.data(), sample.size(), cells, 0x41524749))
    centres.push_back(sample[c]);
  return centres;
}

}  // namespace study
