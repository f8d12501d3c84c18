#include "shadow/crease_wedges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace vlit {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// A wedge whose spanning directions (unit vectors) bound a parallelepiped of volume below this is
// flat: a seam of one surface, hiding a set of no area.
constexpr double kFlatWedge = 1e-9;
// Positions shared by more vertices than this (a pole split into many copies, a malformed mesh
// with all its vertices in one point) get no wedges: the work would grow with the square of the
// group. Their vertices keep the rule without wedges (every triangle touching them hides nothing).
constexpr std::size_t kMaxShared = 64;

// A sum of unit bisectors shorter than this per corner has no direction.
constexpr double kShortSum = 1e-9;

// The indices of the two other corners of triangle t of prim, whose corner v is P.
std::array<std::uint32_t, 2> corners_beside(const ScenePrimitive& prim, std::uint32_t t, std::uint32_t v) {
  const std::uint32_t* idx = &prim.triangles[3 * static_cast<std::size_t>(t)];
  const int k = idx[0] == v ? 0 : idx[1] == v ? 1 : 2;
  return {idx[(k + 1) % 3], idx[(k + 2) % 3]};
}

Vec3d unit_or_zero(const Vec3d& v) {
  const double len = length(v);
  return len > 0 ? v / len : Vec3d{};
}

}  // namespace

SharedPositions::SharedPositions(const Scene& scene) : scene_(scene) {
  struct Entry {
    Vec3d p;
    VertexId id;
  };
  std::vector<Entry> all;
  for (std::size_t pi = 0; pi < scene.primitives.size(); ++pi) {
    const ScenePrimitive& prim = scene.primitives[pi];
    for (std::size_t v = 0; v < prim.positions.size(); ++v)
      if (is_finite(prim.positions[v]))
        all.push_back({prim.positions[v], {static_cast<std::uint32_t>(pi), static_cast<std::uint32_t>(v)}});
  }
  auto key = [](const Entry& e) { return std::tuple(e.p.x, e.p.y, e.p.z, e.id.primitive, e.id.vertex); };
  std::sort(all.begin(), all.end(), [&](const Entry& a, const Entry& b) { return key(a) < key(b); });
  member_of_vertex_.resize(scene.primitives.size());
  for (std::size_t pi = 0; pi < scene.primitives.size(); ++pi)
    member_of_vertex_[pi].assign(scene.primitives[pi].positions.size(), kNone);
  group_first_.push_back(0);
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i + 1;
    while (j < all.size() && all[j].p == all[i].p) ++j;
    if (j - i >= 2 && j - i <= kMaxShared) {
      for (std::size_t k = i; k < j; ++k) {
        member_of_vertex_[all[k].id.primitive][all[k].id.vertex] = static_cast<std::uint32_t>(members_.size());
        members_.push_back(all[k].id);
        group_of_member_.push_back(static_cast<std::uint32_t>(group_first_.size() - 1));
      }
      group_first_.push_back(static_cast<std::uint32_t>(members_.size()));
    }
    i = j;
  }
  // The triangles that use each member vertex (its fan), as lists.
  fan_first_.assign(members_.size() + 1, 0);
  auto for_each_use = [&](auto&& use) {
    for (std::size_t pi = 0; pi < scene.primitives.size(); ++pi) {
      const ScenePrimitive& prim = scene.primitives[pi];
      const std::size_t n = prim.positions.size();
      for (std::size_t t = 0; t + 2 < prim.triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
          const std::uint32_t v = prim.triangles[t + k];
          if (v < n && member_of_vertex_[pi][v] != kNone) use(member_of_vertex_[pi][v], static_cast<std::uint32_t>(t / 3));
        }
    }
  };
  for_each_use([&](std::uint32_t m, std::uint32_t) { ++fan_first_[m + 1]; });
  for (std::size_t m = 0; m < members_.size(); ++m) fan_first_[m + 1] += fan_first_[m];
  fans_.resize(fan_first_.back());
  std::vector<std::uint32_t> fill(fan_first_.begin(), fan_first_.end() - 1);
  for_each_use([&](std::uint32_t m, std::uint32_t t) { fans_[fill[m]++] = t; });
}

CreaseWedges SharedPositions::wedges_of(std::size_t primitive) const {
  const ScenePrimitive& prim = scene_.primitives[primitive];
  const std::size_t n = prim.positions.size();
  CreaseWedges out;
  out.first.assign(n + 1, 0);
  // The unit directions from P along the two sides of triangle t of primitive pi that meet at
  // its corner v; false if a side has no length or a corner is out of range.
  auto sides_at = [&](std::uint32_t pi, std::uint32_t t, std::uint32_t v, Vec3d& e1, Vec3d& e2) {
    const ScenePrimitive& q = scene_.primitives[pi];
    const std::uint32_t* idx = &q.triangles[3 * static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k) {
      if (idx[k] >= q.positions.size()) return false;
    }
    for (int k = 0; k < 3; ++k) {
      if (idx[k] != v) continue;
      const Vec3d& p = q.positions[v];
      e1 = unit_or_zero(q.positions[idx[(k + 1) % 3]] - p);
      e2 = unit_or_zero(q.positions[idx[(k + 2) % 3]] - p);
      return length_squared(e1) > 0 && length_squared(e2) > 0;
    }
    return false;
  };
  for (std::size_t v = 0; v < n; ++v) {
    out.first[v] = static_cast<std::uint32_t>(out.cones.size());
    const std::uint32_t m = member_of_vertex_[primitive][v];
    if (m == kNone) continue;
    // The approach direction d: into the fan, or the vertex normal where the fan is closed
    // around P (every side from P shared by two of its triangles) or empty.
    Vec3d sum{};
    int corners = 0;
    thread_local std::vector<std::pair<std::uint32_t, int>> sides;  // far corner of a side from P, uses
    sides.clear();
    for (std::uint32_t k = fan_first_[m]; k < fan_first_[m + 1]; ++k) {
      Vec3d e1, e2;
      if (!sides_at(static_cast<std::uint32_t>(primitive), fans_[k], static_cast<std::uint32_t>(v), e1, e2)) continue;
      sum += unit_or_zero(e1 + e2);
      ++corners;
      for (const std::uint32_t far : corners_beside(prim, fans_[k], static_cast<std::uint32_t>(v))) {
        auto it = std::find_if(sides.begin(), sides.end(), [&](const auto& s) { return s.first == far; });
        if (it == sides.end()) sides.emplace_back(far, 1);
        else ++it->second;
      }
    }
    const bool closed = corners > 0 && std::all_of(sides.begin(), sides.end(), [](const auto& s) { return s.second == 2; });
    const Vec3d d = !closed && length(sum) > kShortSum * corners ? normalize(sum) : prim.normals[v];
    // The fan's face that d runs along (the one whose plane is nearest to d): the points P + e d
    // lie on it, and it faces the side that the vertex sees.
    Vec3d fan_normal = prim.normals[v];
    double nearest = 2;
    for (std::uint32_t k = fan_first_[m]; k < fan_first_[m + 1]; ++k) {
      Vec3d e1, e2;
      if (!sides_at(static_cast<std::uint32_t>(primitive), fans_[k], static_cast<std::uint32_t>(v), e1, e2)) continue;
      const Vec3d n = unit_or_zero(cross(e1, e2));
      if (length_squared(n) > 0 && std::abs(dot(n, d)) < nearest) {
        nearest = std::abs(dot(n, d));
        fan_normal = n;
      }
    }
    const std::uint32_t g = group_of_member_[m];
    for (std::uint32_t other = group_first_[g]; other < group_first_[g + 1]; ++other) {
      if (other == m) continue;
      for (std::uint32_t k = fan_first_[other]; k < fan_first_[other + 1]; ++k) {
        Vec3d r0, r1;
        if (!sides_at(members_[other].primitive, fans_[k], members_[other].vertex, r0, r1)) continue;
        const Vec3d r2 = -d;
        const double det = dot(r0, cross(r1, r2));
        if (!(std::abs(det) > kFlatWedge)) continue;
        if (det < 0) std::swap(r0, r1);
        // Cut to the side of the fan's plane that the fan faces: a wedge part behind it is reached
        // from the fan only through the fan (the rest of a convex surface past a seam or an edge
        // bends away behind it), and the fan hides nothing from its own vertex.
        const WedgeCone cone{{cross(r1, r2), cross(r2, r0), cross(r0, r1), fan_normal}};
        if (dot(fan_normal, r0) <= 0 && dot(fan_normal, r1) <= 0) continue;  // wholly behind
        out.cones.push_back(cone);
      }
    }
  }
  out.first[n] = static_cast<std::uint32_t>(out.cones.size());
  if (out.cones.empty()) out.first.clear();
  return out;
}

}  // namespace vlit
