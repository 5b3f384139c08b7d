// Writing and strictly reading the fold weights file of argtool tune --fold-weights.
#include "eval/set_weights_file.hpp"

#include "common/errors.hpp"
#include "match/weights.hpp"

namespace arg {

namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::string format_set_weights(const std::vector<SetWeights>& folds) {
  std::string out;
  for (const SetWeights& f : folds) out += f.set + " " + f.weights + "\n";
  return out;
}

std::vector<SetWeights> parse_set_weights(std::string_view text) {
  std::vector<SetWeights> folds;
  std::size_t at = 0;
  for (int line_number = 1; at < text.size(); ++line_number) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(at, end - at));
    at = end + 1;
    if (line.empty() || line.front() == '#') continue;
    const std::string where = "fold weights: line " + std::to_string(line_number);
    const std::size_t gap = line.find_first_of(" \t");
    if (gap == std::string_view::npos) throw InputError(where + ": a set name without weights");
    SetWeights fold{std::string(line.substr(0, gap)), std::string(trim(line.substr(gap)))};
    try {
      parse_weights(fold.weights);
    } catch (const InputError& e) {
      throw InputError(where + ": " + e.what());
    }
    for (const SetWeights& seen : folds)
      if (seen.set == fold.set) throw InputError(where + ": set " + fold.set + " named twice");
    folds.push_back(std::move(fold));
  }
  return folds;
}

}  // namespace arg
