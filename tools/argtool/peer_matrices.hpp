// The peers' distance matrices of a labelled set, as ../shared/peers keeps them.
#pragma once

#include <string>
#include <vector>

#include "eval/distance_matrix_file.hpp"

namespace argtool {

struct PeerMatrix {
  std::string method;  // the file's name before ".dist": "shd", "mrg-bespalov"
  arg::DistanceMatrix matrix;
};

// Every DIR/SET/METHOD.dist.txt.gz (or plain .dist.txt): a line per model in the set's label
// order, distances separated by any whitespace. By method name; none when DIR/SET is absent.
// Throws std::runtime_error naming the file when one is unreadable or not `models` square.
std::vector<PeerMatrix> read_peer_matrices(const std::string& dir, const std::string& set,
                                           std::size_t models);

// The column heading of a peer: its name up to the first '-', in capitals ("MRG" for
// "mrg-bespalov"), as the literature names the methods.
std::string peer_heading(const std::string& method);

}  // namespace argtool
