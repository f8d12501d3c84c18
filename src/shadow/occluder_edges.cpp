#include "shadow/occluder_edges.h"

#include <omp.h>

#include <algorithm>

#include <boost/sort/block_indirect_sort/block_indirect_sort.hpp>

#include "shadow/convex_volume.h"

namespace vlit {

OccluderEdges edges_of(const OccluderTriangles& triangles) {
  const long n = static_cast<long>(triangles.size());
  struct Side {
    Vec3d a, b;           // lexicographic order
    std::uint32_t code;   // 3 * triangle + side
    std::int8_t direction;
  };
  std::vector<Side> sides(3 * n);
#pragma omp parallel for schedule(static)
  for (long t = 0; t < n; ++t)
    for (int j = 0; j < 3; ++j) {
      const Vec3d& x = triangles.corners[t][j];
      const Vec3d& y = triangles.corners[t][(j + 1) % 3];
      const bool forward = !lexicographic_less(y, x);
      sides[3 * t + j] = {forward ? x : y, forward ? y : x, static_cast<std::uint32_t>(3 * t + j),
                          static_cast<std::int8_t>(forward ? 1 : -1)};
    }
  auto key_less = [](const Side& p, const Side& q) {
    if (p.a != q.a) return lexicographic_less(p.a, q.a);
    if (p.b != q.b) return lexicographic_less(p.b, q.b);
    return p.code < q.code;
  };
  // A total order (ties by code), so the parallel sort gives the serial one's result.
  boost::sort::block_indirect_sort(sides.begin(), sides.end(), key_less,
                                   static_cast<std::uint32_t>(std::max(1, omp_get_max_threads())));

  // Runs of equal endpoints are the edges (a run's first side has the smallest code).
  constexpr std::uint32_t kUnset = ~std::uint32_t{0};
  std::vector<std::uint32_t> run_of_code(sides.size()), run_start;
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (i == 0 || !(sides[i].a == sides[run_start.back()].a && sides[i].b == sides[run_start.back()].b))
      run_start.push_back(static_cast<std::uint32_t>(i));
    run_of_code[sides[i].code] = static_cast<std::uint32_t>(run_start.size() - 1);
  }
  const std::size_t edge_count = run_start.size();
  run_start.push_back(static_cast<std::uint32_t>(sides.size()));
  // The edges numbered in the order the triangles first name them, so that the edges of
  // neighbouring triangles (stored together) are stored together too.
  std::vector<std::uint32_t> edge_of_run(edge_count, kUnset), run_of_edge;
  run_of_edge.reserve(edge_count);
  for (std::uint32_t run : run_of_code)
    if (edge_of_run[run] == kUnset) {
      edge_of_run[run] = static_cast<std::uint32_t>(run_of_edge.size());
      run_of_edge.push_back(run);
    }

  OccluderEdges edges;
  edges.edge_of.resize(n);
  edges.direction_of.resize(n);
  edges.has_open_edge.assign(n, 0);
  edges.endpoints.resize(edge_count);
  edges.first_incident.resize(edge_count + 1);
  edges.incident.resize(sides.size());
  edges.first_incident[0] = 0;
  for (std::size_t e = 0; e < edge_count; ++e)
    edges.first_incident[e + 1] = edges.first_incident[e] + (run_start[run_of_edge[e] + 1] - run_start[run_of_edge[e]]);
  // An edge is open unless exactly two sides of opposite directions share it.
  std::vector<std::uint8_t> open(edge_count);
#pragma omp parallel for schedule(static)
  for (long e = 0; e < static_cast<long>(edge_count); ++e) {
    const std::uint32_t begin = run_start[run_of_edge[e]], end = run_start[run_of_edge[e] + 1];
    edges.endpoints[e] = {sides[begin].a, sides[begin].b};
    int balance = 0;
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t code = sides[k].code;
      balance += sides[k].direction;
      edges.incident[edges.first_incident[e] + (k - begin)] = code;
      edges.edge_of[code / 3][code % 3] = static_cast<std::uint32_t>(e);
      edges.direction_of[code / 3][code % 3] = sides[k].direction;
    }
    open[e] = end - begin != 2 || balance != 0;
  }
#pragma omp parallel for schedule(static)
  for (long t = 0; t < n; ++t)
    for (std::uint32_t e : edges.edge_of[t]) edges.has_open_edge[t] |= open[e];
  return edges;
}

}  // namespace vlit
