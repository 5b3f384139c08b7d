// Sine and cosine from + - * / only, so angles give the same bits under every C library.
#pragma once

namespace arg::gen {

constexpr double kPi = 3.14159265358979323846;

// std::sin and std::cos differ in the last bit between libms; these use a fixed range
// reduction and polynomial, accurate to about 1e-16 for |x| < 1e6.
double portable_sin(double x);
double portable_cos(double x);

inline double degrees(double deg) {
  return deg * (kPi / 180.0);
}

}  // namespace arg::gen
