// The text form of a full distance matrix, for scorers outside the project.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace arg {

struct DistanceMatrix {
  std::size_t n = 0;
  std::vector<double> distance;  // row-major n x n; row = query
  std::vector<bool> valid;       // false: the model failed to build (its row and column are inf)
};

// One line per model in label order, n numbers separated by single spaces, each printed
// exactly (the shortest form that reads back to the same double); a failed model's row and
// column are "inf".
std::string format_distance_matrix(const DistanceMatrix& m);

// Reads that form back: n lines of n numbers ("inf" allowed; a model whose own distance is
// inf is a failed one). Throws InputError naming the line for a wrong count or a bad number.
DistanceMatrix parse_distance_matrix(std::string_view text);

}  // namespace arg
