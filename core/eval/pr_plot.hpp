// Precision-recall curves drawn as a standalone SVG.
#pragma once

#include <string>
#include <vector>

namespace arg {

struct PrCurve {
  std::string name;
  std::vector<double> precision;  // at recall 1/k .. 1 for k points
};

std::string precision_recall_svg(const std::vector<PrCurve>& curves, const std::string& title);

}  // namespace arg
