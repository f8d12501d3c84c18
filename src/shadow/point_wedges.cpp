#include "shadow/point_wedges.h"

#include <bit>
#include <unordered_map>

namespace vlit {
namespace {

// Exact positions as keys: a point is on a vertex only when it has the vertex's coordinates bit
// for bit (snap_to_vertices puts it there).
struct PositionKey {
  std::uint64_t x, y, z;
  bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint64_t v : {k.x, k.y, k.z}) h = (h ^ v) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

PositionKey key_of(const Vec3d& p) {
  // +0.0 for -0.0, so that the two zeros meet.
  return {std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0),
          std::bit_cast<std::uint64_t>(p.z + 0.0)};
}

}  // namespace

PointWedges::PointWedges(const Scene& scene, std::span<const Vec3d> positions, std::span<const Vec3d> normals)
    : primitive_(positions.size(), kNone), vertex_(positions.size(), kNone) {
  std::unordered_map<PositionKey, std::size_t, PositionHash> point_at;  // a position -> first point there
  std::vector<std::size_t> next_point(positions.size(), positions.size());  // other points at the same position
  for (std::size_t i = positions.size(); i-- > 0;) {
    auto [it, fresh] = point_at.try_emplace(key_of(positions[i]), i);
    if (!fresh) {
      next_point[i] = it->second;
      it->second = i;
    }
  }
  std::vector<double> best(positions.size(), -2);
  for (std::size_t pi = 0; pi < scene.primitives.size(); ++pi) {
    const ScenePrimitive& prim = scene.primitives[pi];
    for (std::size_t v = 0; v < prim.positions.size(); ++v) {
      const auto it = point_at.find(key_of(prim.positions[v]));
      if (it == point_at.end()) continue;
      for (std::size_t i = it->second; i < positions.size(); i = next_point[i]) {
        const double along = dot(prim.normals[v], normalize(normals[i]));
        if (along > best[i]) {
          best[i] = along;
          primitive_[i] = static_cast<std::uint32_t>(pi);
          vertex_[i] = static_cast<std::uint32_t>(v);
        }
      }
    }
  }
  std::vector<bool> needed(scene.primitives.size(), false);
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (primitive_[i] != kNone) {
      needed[primitive_[i]] = true;
      ++on_vertex_;
    }
  of_primitive_.resize(scene.primitives.size());
  if (on_vertex_ == 0) return;
  const SharedPositions shared(scene);
  for (std::size_t pi = 0; pi < scene.primitives.size(); ++pi)
    if (needed[pi]) of_primitive_[pi] = shared.wedges_of(pi);
}

std::span<const WedgeCone> PointWedges::of(std::size_t point) const {
  if (point >= primitive_.size() || primitive_[point] == kNone) return {};
  return of_primitive_[primitive_[point]].of(vertex_[point]);
}

}  // namespace vlit
