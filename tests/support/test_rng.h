// Seeded random numbers for the kernel tests: uniform and log-uniform scalars and uniform unit
// directions, reproducible from the seed a failing test prints.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "core/vec3.h"

namespace vlit::test {

struct Rng {
  std::mt19937_64 gen;
  explicit Rng(std::uint64_t seed) : gen(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }
  double log_uniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
  // Rejection sampling in the unit ball, away from the origin so the normalization is exact enough.
  Vec3d unit() {
    for (;;) {
      const Vec3d v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      const double l2 = length_squared(v);
      if (l2 > 1e-4 && l2 <= 1) return v / std::sqrt(l2);
    }
  }
};

}  // namespace vlit::test
