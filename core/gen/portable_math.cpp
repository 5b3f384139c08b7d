// Sine and cosine from + - * / only, so angles give the same bits under every C library.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "gen/portable_math.hpp"

#include <cmath>

namespace arg::gen {
namespace {

// Cody-Waite split of pi/2: k * kHalfPiHigh is exact for the |k| we meet, so the
// reduced argument keeps its precision.
constexpr double kHalfPiHigh = 1.57079632673412561417e+00;
constexpr double kHalfPiLow = 6.07710050650619224932e-11;

// Taylor series on [-pi/4, pi/4]; the first dropped term is below 1e-18.
double sin_reduced(double r) {
  const double r2 = r * r;
  double p = 1.0 / 355687428096000.0;  // 1/17!
  p = p * r2 - 1.0 / 1307674368000.0;
  p = p * r2 + 1.0 / 6227020800.0;
  p = p * r2 - 1.0 / 39916800.0;
  p = p * r2 + 1.0 / 362880.0;
  p = p * r2 - 1.0 / 5040.0;
  p = p * r2 + 1.0 / 120.0;
  p = p * r2 - 1.0 / 6.0;
  return r + r * r2 * p;
}

double cos_reduced(double r) {
  const double r2 = r * r;
  double p = 1.0 / 6402373705728000.0;  // 1/18!
  p = p * r2 - 1.0 / 20922789888000.0;
  p = p * r2 + 1.0 / 87178291200.0;
  p = p * r2 - 1.0 / 479001600.0;
  p = p * r2 + 1.0 / 3628800.0;
  p = p * r2 - 1.0 / 40320.0;
  p = p * r2 + 1.0 / 720.0;
  p = p * r2 - 1.0 / 24.0;
  p = p * r2 + 0.5;
  return 1.0 - r2 * p;
}

// Returns the quadrant and writes the remainder in [-pi/4, pi/4].
long long reduce(double x, double* r) {
  const double k = std::nearbyint(x * (2.0 / kPi));
  *r = (x - k * kHalfPiHigh) - k * kHalfPiLow;
  return static_cast<long long>(k);
}

}  // namespace

double portable_sin(double x) {
  double r = 0;
  switch (reduce(x, &r) & 3) {
    case 0:
      return sin_reduced(r);
    case 1:
      return cos_reduced(r);
    case 2:
      return -sin_reduced(r);
    default:
      return -cos_reduced(r);
  }
}

double portable_cos(double x) {
  double r = 0;
  switch (reduce(x, &r) & 3) {
    case 0:
      return cos_reduced(r);
    case 1:
      return -sin_reduced(r);
    case 2:
      return -cos_reduced(r);
    default:
      return sin_reduced(r);
  }
}

}  // namespace arg::gen
