// The weights each leave-one-set-out fold learnt, by the set it held out (tune writes, eval reads).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace arg {

struct SetWeights {
  std::string set;      // the held-out set's name (argtool's set_name: "shrec07")
  std::string weights;  // weights text learnt on the other sets (format_weights' form)
};

// One line per fold: the set's name, a space, the weights text.
std::string format_set_weights(const std::vector<SetWeights>& folds);

// Reads that form back; blank lines and lines starting with '#' are skipped, so a file can say
// where its weights came from. Throws InputError naming the line for a line without weights,
// weights parse_weights refuses, or a set named twice.
std::vector<SetWeights> parse_set_weights(std::string_view text);

}  // namespace arg
