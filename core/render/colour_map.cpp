// Turbo as a fifth-degree polynomial (Mikhailov 2019) and a qualitative palette for pairs.
#include "render/colour_map.hpp"

#include <algorithm>
#include <cmath>

namespace arg {

Rgb mu_colour(double t) {
  const double x = 0.06 + 0.86 * std::clamp(t, 0.0, 1.0);
  const double x2 = x * x, x3 = x2 * x, x4 = x2 * x2, x5 = x4 * x;
  const double r = 0.13572138 + 4.61539260 * x - 42.66032258 * x2 + 132.13108234 * x3 -
                   152.94239396 * x4 + 59.28637943 * x5;
  const double g = 0.09140261 + 2.19418839 * x + 4.84296658 * x2 - 14.18503333 * x3 +
                   4.27729857 * x4 + 2.82956604 * x5;
  const double b = 0.10667330 + 12.64194608 * x - 60.58204836 * x2 + 110.36276771 * x3 -
                   89.90310912 * x4 + 27.34824973 * x5;
  auto byte = [](double v) { return std::uint8_t(std::lround(255 * std::clamp(v, 0.0, 1.0))); };
  return {byte(r), byte(g), byte(b)};
}

Rgb pair_colour(int k) {
  static const Rgb palette[] = {{31, 119, 180},  {255, 127, 14}, {44, 160, 44},   {214, 39, 40},
                                {148, 103, 189}, {140, 86, 75},  {227, 119, 194}, {188, 189, 34},
                                {23, 190, 207},  {255, 200, 0},  {0, 128, 128},   {128, 0, 64}};
  const int n = int(sizeof palette / sizeof palette[0]);
  k = std::max(k, 0);
  const int round = k / n;
  const Rgb c = palette[k % n];
  if (round == 0) return c;
  // Later rounds alternate darker and lighter versions, each a little further from the first.
  const double step = 0.18 * ((round + 1) / 2);
  if (round % 2) return scaled(c, std::max(0.35, 1.0 - step));
  auto lift = [step](std::uint8_t v) {
    return std::uint8_t(std::lround(v + (255 - v) * std::min(step, 0.6)));
  };
  return {lift(c.r), lift(c.g), lift(c.b)};
}

}  // namespace arg
