#include "shadow/snap_to_vertices.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "shadow/convex_volume.h"

namespace vlit {
namespace {

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int64_t x : c) h = (h ^ static_cast<std::uint64_t>(x)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

SnapCount snap_to_vertices(const OccluderTriangles& triangles, std::vector<Vec3d>& points) {
  SnapCount count;
  Aabb bounds;
  for (const auto& tri : triangles.corners)
    for (const Vec3d& c : tri) bounds.grow(c);
  const double tolerance = kSnapTolerance * length(bounds.hi - bounds.lo);
  if (!(tolerance > 0) || !std::isfinite(tolerance)) return count;
  // The distinct corners, in a grid of cells as wide as the tolerance.
  auto cell_of = [&](const Vec3d& p) {
    return Cell{static_cast<std::int64_t>(std::floor((p.x - bounds.lo.x) / tolerance)),
                static_cast<std::int64_t>(std::floor((p.y - bounds.lo.y) / tolerance)),
                static_cast<std::int64_t>(std::floor((p.z - bounds.lo.z) / tolerance))};
  };
  std::unordered_map<Cell, std::vector<Vec3d>, CellHash> grid;
  for (const auto& tri : triangles.corners)
    for (const Vec3d& c : tri) {
      std::vector<Vec3d>& in_cell = grid[cell_of(c)];
      bool known = false;
      for (const Vec3d& x : in_cell) known = known || x == c;
      if (!known) in_cell.push_back(c);
    }
  for (Vec3d& p : points) {
    if (!is_finite(p)) continue;
    const Cell home = cell_of(p);
    const Vec3d* found = nullptr;
    int near = 0;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(Cell{home[0] + dx, home[1] + dy, home[2] + dz});
          if (it == grid.end()) continue;
          for (const Vec3d& c : it->second)
            if (length(c - p) <= tolerance) {
              found = &c;
              ++near;
            }
        }
    if (near == 1) {
      p = *found;
      ++count.snapped;
    } else if (near > 1) {
      ++count.ambiguous;
    }
  }
  return count;
}

}  // namespace vlit
