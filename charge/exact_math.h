// exact_math.h - floor, ceil and remainder by 2 pi without the libm calls, with
// the same values as std::floor, std::ceil and std::remainder(x, 2 pi) where
// stated. Internal to the charge models' hot loops (the layer model, its slot
// maps, the liner ride table, the occupancy bins): truncation is one SSE2
// instruction where the libm call is a function call per cell or bin.
#pragma once

#include <cmath>

#include "geometry/mill.h"  // kPi

namespace linerlife {

/// std::floor(x) for |x| < 2^62.
inline double floor_exact(double x) {
  const double t = static_cast<double>(static_cast<long long>(x));
  return t > x ? t - 1.0 : t;
}

/// std::ceil(x) for |x| < 2^62.
inline double ceil_exact(double x) {
  const double t = static_cast<double>(static_cast<long long>(x));
  return t < x ? t + 1.0 : t;
}

/// floor(x) as an int, |x| < 2^31.
inline int floor_int(double x) {
  const int t = static_cast<int>(x);
  return static_cast<double>(t) > x ? t - 1 : t;
}

/// ceil(x) as an int, |x| < 2^31.
inline int ceil_int(double x) {
  const int t = static_cast<int>(x);
  return static_cast<double>(t) < x ? t + 1 : t;
}

/// floor(x) as a long long, |x| < 2^62.
inline long long floor_ll(double x) {
  const long long t = static_cast<long long>(x);
  return static_cast<double>(t) > x ? t - 1 : t;
}

/// std::remainder(x, 2 pi), without the libm call where |x| < 2 pi: x itself
/// up to pi (at pi the tie goes to the even quotient 0), else x -+ 2 pi, which
/// is exact there (Sterbenz) and so what std::remainder returns.
inline double remainder_2pi(double x) {
  constexpr double two_pi = 2.0 * kPi;
  const double ax = std::abs(x);
  if (ax <= kPi) return x;
  if (ax < two_pi) return x > 0 ? x - two_pi : x + two_pi;
  return std::remainder(x, two_pi);
}

}  // namespace linerlife
