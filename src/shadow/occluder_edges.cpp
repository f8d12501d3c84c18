#include "shadow/occluder_edges.h"

#include <algorithm>

#include "shadow/convex_volume.h"

namespace vlit {

namespace {

// The edges numbered in the order the triangles first name them, so that the edges of
// neighbouring triangles (stored together) are stored together too.
OccluderEdges renumbered_by_triangles(const OccluderEdges& in) {
  const std::size_t edge_count = in.size();
  constexpr std::uint32_t kUnset = ~std::uint32_t{0};
  std::vector<std::uint32_t> new_of(edge_count, kUnset), old_of;
  old_of.reserve(edge_count);
  for (const auto& sides : in.edge_of)
    for (std::uint32_t e : sides)
      if (new_of[e] == kUnset) {
        new_of[e] = static_cast<std::uint32_t>(old_of.size());
        old_of.push_back(e);
      }
  OccluderEdges out;
  out.direction_of = in.direction_of;
  out.has_open_edge = in.has_open_edge;
  out.edge_of = in.edge_of;
  for (auto& sides : out.edge_of)
    for (std::uint32_t& e : sides) e = new_of[e];
  out.endpoints.reserve(edge_count);
  out.first_incident.reserve(edge_count + 1);
  out.incident.reserve(in.incident.size());
  for (std::uint32_t old : old_of) {
    out.endpoints.push_back(in.endpoints[old]);
    out.first_incident.push_back(static_cast<std::uint32_t>(out.incident.size()));
    for (std::uint32_t k = in.first_incident[old]; k < in.first_incident[old + 1]; ++k) out.incident.push_back(in.incident[k]);
  }
  out.first_incident.push_back(static_cast<std::uint32_t>(out.incident.size()));
  return out;
}

}  // namespace

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
  return renumbered_by_triangles(edges);
}

}  // namespace vlit
