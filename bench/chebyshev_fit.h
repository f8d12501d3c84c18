// Polynomial fits for the float batch kernels' elementary functions (shaders_cpu/batch/): the
// degree-DEG polynomial that interpolates f at the DEG + 1 Chebyshev nodes of [a, b]
// (near-minimax), computed in long double and converted from the Chebyshev to the monomial basis
// for Horner evaluation. Used by bench/fit_atan_polynomial.cpp and bench/fit_log_polynomial.cpp.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <vector>

namespace vlit::fit {

using LD = long double;

// Monomial coefficients (z^0 first) of the interpolant of f on [a, b].
template <class F>
std::vector<LD> chebyshev_interpolant(F f, LD a, LD b, int deg) {
  const int n = deg + 1;
  // Chebyshev coefficients c_j of f in w = alpha z + beta, which maps [a, b] to [-1, 1].
  const LD alpha = 2 / (b - a), beta = -(a + b) / (b - a);
  std::vector<LD> c(n, 0);
  for (int j = 0; j < n; ++j) {
    LD sum = 0;
    for (int k = 0; k < n; ++k) {
      const LD theta = M_PIl * (k + 0.5L) / n;
      sum += f(a + (std::cos(theta) + 1) / 2 * (b - a)) * std::cos(j * theta);
    }
    c[j] = (j == 0 ? 1 : 2) * sum / n;
  }
  // T_j(alpha z + beta) as polynomials in z, by T_{j+1} = 2 w T_j - T_{j-1}; accumulate Σ c_j T_j.
  std::vector<LD> prev(n, 0), cur(n, 0), mono(n, 0);
  prev[0] = 1;
  if (n > 1) { cur[0] = beta; cur[1] = alpha; }
  for (int i = 0; i < n; ++i) mono[i] += c[0] * prev[i] + (n > 1 ? c[1] * cur[i] : 0);
  for (int j = 2; j < n; ++j) {
    std::vector<LD> next(n, 0);
    for (int i = 0; i < n; ++i) next[i] = 2 * beta * cur[i] - prev[i] + (i > 0 ? 2 * alpha * cur[i - 1] : 0);
    for (int i = 0; i < n; ++i) mono[i] += c[j] * next[i];
    prev = cur;
    cur = next;
  }
  return mono;
}

// The command line of the fit programs: `NAME [DEGREE] [--double]`, the degree in [1, max_degree]
// (default_degree when absent), --double for the double kernels' range. Prints the usage and
// returns nothing for anything else.
struct FitArguments {
  int degree;
  bool double_range;
};
inline std::optional<FitArguments> fit_arguments(int argc, char** argv, const char* name, int default_degree,
                                                 int max_degree) {
  const int degree = argc > 1 ? std::atoi(argv[1]) : default_degree;
  const bool double_range = argc > 2 && std::strcmp(argv[2], "--double") == 0;
  if (degree < 1 || degree > max_degree || (argc > 2 && !double_range) || argc > 3) {
    std::fprintf(stderr, "usage: %s [DEGREE 1..%d] [--double]\n", name, max_degree);
    return std::nullopt;
  }
  return FitArguments{degree, double_range};
}

}  // namespace vlit::fit
