#include "shadow/occluder_edges.h"

#include <algorithm>

#include "shadow/convex_volume.h"

namespace vlit {

OccluderEdges edges_of(const OccluderTriangles& triangles) {
  const std::size_t n = triangles.size();
  struct Side {
    Vec3d a, b;           // lexicographic order
    std::uint32_t code;   // 3 * triangle + side
    std::int8_t direction;
  };
  std::vector<Side> sides;
  sides.reserve(3 * n);
  for (std::size_t t = 0; t < n; ++t)
    for (int j = 0; j < 3; ++j) {
      const Vec3d& x = triangles.corners[t][j];
      const Vec3d& y = triangles.corners[t][(j + 1) % 3];
      const bool forward = !lexicographic_less(y, x);
      sides.push_back({forward ? x : y, forward ? y : x, static_cast<std::uint32_t>(3 * t + j),
                       static_cast<std::int8_t>(forward ? 1 : -1)});
    }
  auto key_less = [](const Side& p, const Side& q) {
    if (p.a != q.a) return lexicographic_less(p.a, q.a);
    if (p.b != q.b) return lexicographic_less(p.b, q.b);
    return p.code < q.code;
  };
  std::sort(sides.begin(), sides.end(), key_less);

  OccluderEdges edges;
  edges.edge_of.resize(n);
  edges.direction_of.resize(n);
  edges.has_open_edge.assign(n, 0);
  edges.incident.reserve(sides.size());
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    int balance = 0;
    while (j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b) balance += sides[j++].direction;
    const auto e = static_cast<std::uint32_t>(edges.endpoints.size());
    edges.endpoints.push_back({sides[i].a, sides[i].b});
    edges.first_incident.push_back(static_cast<std::uint32_t>(edges.incident.size()));
    const bool open = j - i != 2 || balance != 0;
    for (std::size_t k = i; k < j; ++k) {
      const std::uint32_t t = sides[k].code / 3, side = sides[k].code % 3;
      edges.edge_of[t][side] = e;
      edges.direction_of[t][side] = sides[k].direction;
      edges.incident.push_back(sides[k].code);
      if (open) edges.has_open_edge[t] = 1;
    }
    i = j;
  }
  edges.first_incident.push_back(static_cast<std::uint32_t>(edges.incident.size()));
  return edges;
}

}  // namespace vlit
