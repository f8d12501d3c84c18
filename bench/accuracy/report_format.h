// How the accuracy report prints a number: errors with two significant digits ("n/a" where a
// method does not apply, "**inf**" for a non-finite result), times in ns with k / M suffixes.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace vlit::bench::accuracy {

inline std::string fmt(double x) {
  if (std::isnan(x)) return "n/a";
  if (std::isinf(x)) return "**inf**";
  if (x == 0) return "0";
  char b[32];
  std::snprintf(b, sizeof b, "%.1e", x);
  return b;
}

inline std::string fmt_ns(double x) {
  char b[32];
  if (x < 1e4) std::snprintf(b, sizeof b, "%.0f", x);
  else if (x < 1e6) std::snprintf(b, sizeof b, "%.1f k", x / 1e3);
  else std::snprintf(b, sizeof b, "%.2f M", x / 1e6);
  return b;
}

// A tolerance as a key: 1e-4 -> "1e-4" (the printed labels use %g: "0.0001").
inline std::string tol_key(double tol) {
  char b[32];
  std::snprintf(b, sizeof b, "%.0e", tol);
  std::string s(b);
  const std::size_t e = s.find('e');
  std::size_t d = e + 2;  // first exponent digit after the sign
  while (d + 1 < s.size() && s[d] == '0') s.erase(d, 1);
  return s;
}

}  // namespace vlit::bench::accuracy
