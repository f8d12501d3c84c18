#include "mesh/planar_polygons.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace vlit {
namespace {

// Exact position -> welded id.
struct PositionKey {
  std::uint64_t bits[3];
  bool operator==(const PositionKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};
struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint64_t b : k.bits) h = (h ^ b) * 1099511628211ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

PositionKey key_of(const Vec3d& p) {
  PositionKey k{};
  const double c[3] = {p.x == 0 ? 0.0 : p.x, p.y == 0 ? 0.0 : p.y, p.z == 0 ? 0.0 : p.z};  // -0 == +0
  std::memcpy(k.bits, c, sizeof k.bits);
  return k;
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }

// Relative tolerances: same facing within ~1.4e-5 rad, on the seed's plane within 1e-7 of the
// seed's size (the area kernels accept 1e-6 of the polygon's radius).
constexpr double kNormalDot = 1 - 1e-10;
constexpr double kPlaneTolerance = 1e-7;

struct Triangle {
  std::uint32_t v[3];  // welded ids
  Vec3d normal;        // unit
  double size = 0;     // longest edge
};

// Drops boundary vertices where the loop goes straight on (relative to the edge lengths).
std::vector<Vec3d> drop_collinear(const std::vector<Vec3d>& loop) {
  std::vector<Vec3d> out = loop;
  bool changed = true;
  while (changed && out.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < out.size() && out.size() > 3; ++i) {
      const Vec3d& prev = out[(i + out.size() - 1) % out.size()];
      const Vec3d& next = out[(i + 1) % out.size()];
      const Vec3d a = out[i] - prev, b = next - out[i];
      if (length(cross(a, b)) <= 1e-12 * length(a) * length(b) && dot(a, b) > 0) {
        out.erase(out.begin() + static_cast<long>(i));
        changed = true;
        --i;
      }
    }
  }
  return out;
}

bool planar(const std::vector<Vec3d>& polygon) {
  Vec3d c, newell;
  for (const Vec3d& q : polygon) c += q;
  c = c / static_cast<double>(polygon.size());
  double radius = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    newell += cross(polygon[i] - c, polygon[(i + 1) % polygon.size()] - c);
    radius = std::max(radius, length(polygon[i] - c));
  }
  const double twice_area = length(newell);
  if (!(twice_area > 0)) return false;
  const Vec3d n = newell / twice_area;
  for (const Vec3d& q : polygon)
    if (std::abs(dot(q - c, n)) > kPlaneTolerance * radius) return false;
  return true;
}

}  // namespace

std::vector<std::vector<Vec3d>> merge_coplanar_triangles(const std::vector<Vec3d>& positions,
                                                         const std::vector<std::uint32_t>& triangles,
                                                         std::size_t max_vertices, PlanarMergeStats* stats) {
  PlanarMergeStats local;
  PlanarMergeStats& st = stats ? *stats : local;
  st = {};
  // Weld by exact position.
  std::vector<Vec3d> welded;
  std::vector<std::uint32_t> id_of(positions.size());
  {
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> ids;
    ids.reserve(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const auto [it, inserted] = ids.emplace(key_of(positions[i]), static_cast<std::uint32_t>(welded.size()));
      if (inserted) welded.push_back(positions[i]);
      id_of[i] = it->second;
    }
  }
  std::vector<Triangle> tris;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    Triangle tri;
    for (int k = 0; k < 3; ++k) tri.v[k] = id_of[triangles[t + k]];
    if (tri.v[0] == tri.v[1] || tri.v[1] == tri.v[2] || tri.v[0] == tri.v[2]) continue;
    const Vec3d a = welded[tri.v[0]], b = welded[tri.v[1]], c = welded[tri.v[2]];
    const Vec3d n = cross(b - a, c - a);
    tri.size = std::sqrt(std::max({length_squared(b - a), length_squared(c - b), length_squared(a - c)}));
    const double len = length(n);
    if (!(len > 1e-12 * tri.size * tri.size) || !std::isfinite(len)) continue;  // degenerate
    tri.normal = n / len;
    tris.push_back(tri);
  }
  st.triangles = tris.size();

  // Directed edge -> triangle; an undirected edge used more than twice is non-manifold.
  std::unordered_map<std::uint64_t, std::uint32_t> edge_owner;
  std::unordered_map<std::uint64_t, int> edge_uses;
  edge_owner.reserve(3 * tris.size());
  for (std::uint32_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tris[t].v[k], b = tris[t].v[(k + 1) % 3];
      edge_owner[edge_key(a, b)] = t;
      ++edge_uses[edge_key(std::min(a, b), std::max(a, b))];
    }
  auto neighbour = [&](std::uint32_t t, int k) -> long {
    const std::uint32_t a = tris[t].v[k], b = tris[t].v[(k + 1) % 3];
    if (edge_uses[edge_key(std::min(a, b), std::max(a, b))] != 2) return -1;
    const auto it = edge_owner.find(edge_key(b, a));
    return it == edge_owner.end() ? -1 : static_cast<long>(it->second);
  };

  std::vector<std::vector<Vec3d>> polygons;
  std::vector<int> region_of(tris.size(), -1);
  std::vector<std::uint32_t> region, stack;
  for (std::uint32_t seed = 0; seed < tris.size(); ++seed) {
    if (region_of[seed] >= 0) continue;
    const int r = static_cast<int>(st.regions++);
    // Flood fill through manifold edges to triangles on the seed's plane, facing the same way.
    const Vec3d n0 = tris[seed].normal, q0 = welded[tris[seed].v[0]];
    const double tolerance = kPlaneTolerance * tris[seed].size;
    region.clear();
    stack.assign(1, seed);
    region_of[seed] = r;
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      region.push_back(t);
      for (int k = 0; k < 3; ++k) {
        const long u = neighbour(t, k);
        if (u < 0 || region_of[u] >= 0 || dot(tris[u].normal, n0) < kNormalDot) continue;
        bool on_plane = true;
        for (std::uint32_t v : tris[u].v) on_plane = on_plane && std::abs(dot(welded[v] - q0, n0)) <= tolerance;
        if (!on_plane) continue;
        region_of[u] = r;
        stack.push_back(static_cast<std::uint32_t>(u));
      }
    }

    // Boundary: directed edges whose reverse is not in the region. One outgoing edge per vertex
    // and a single cycle through all of them make a simple polygon without holes.
    std::unordered_map<std::uint32_t, std::uint32_t> next;
    bool simple = true;
    std::size_t boundary_edges = 0;
    for (std::uint32_t t : region)
      for (int k = 0; k < 3 && simple; ++k) {
        const std::uint32_t a = tris[t].v[k], b = tris[t].v[(k + 1) % 3];
        const auto it = edge_owner.find(edge_key(b, a));
        if (it != edge_owner.end() && region_of[it->second] == r && neighbour(t, k) >= 0) continue;
        ++boundary_edges;
        simple = next.emplace(a, b).second;  // a second outgoing edge: pinched boundary
      }
    std::vector<Vec3d> loop;
    if (simple && region.size() > 1) {
      std::uint32_t v = next.begin()->first;
      for (std::size_t step = 0; step < boundary_edges; ++step) {
        loop.push_back(welded[v]);
        const auto it = next.find(v);
        if (it == next.end()) { simple = false; break; }
        v = it->second;
        if (v == next.begin()->first) break;
      }
      simple = simple && loop.size() == boundary_edges;  // else: several loops (holes)
      if (simple) loop = drop_collinear(loop);
      simple = simple && loop.size() >= 3 && loop.size() <= max_vertices && planar(loop);
    }
    if (simple && region.size() > 1) {
      ++st.merged_regions;
      polygons.push_back(std::move(loop));
    } else {
      if (region.size() == 1) ++st.merged_regions;
      for (std::uint32_t t : region)
        polygons.push_back({welded[tris[t].v[0]], welded[tris[t].v[1]], welded[tris[t].v[2]]});
    }
  }
  return polygons;
}

}  // namespace vlit
