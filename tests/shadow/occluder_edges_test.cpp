// The occluder edges against a brute-force pairing of triangle sides by their endpoints, and the
// occluder BVH and edges built on two threads against the same built on one.
#include <doctest/doctest.h>

#include <omp.h>

#include <algorithm>
#include <random>
#include <tuple>

#include "shadow_test_util.h"
#include "shadow/area_visibility.h"

using namespace vlit;
using namespace vlit::test;

namespace {

OccluderTriangles triangles_of(const std::vector<Tri>& tris) {
  OccluderTriangles t;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    t.corners.push_back(tris[i]);
    t.ids.push_back({0, static_cast<std::uint32_t>(i)});
  }
  return t;
}

// A closed sphere, plus what the pairing must cope with: a copy of a face (a non-manifold edge
// of three sides), a face wound against its neighbours, an open strip, a zero-length side, and
// an edge named once with -0 and once with +0 in a coordinate.
std::vector<Tri> awkward_mesh() {
  std::vector<Tri> tris = icosphere({0, 0, 0}, 1, 2);
  tris.push_back(tris[7]);
  tris[20] = {tris[20][0], tris[20][2], tris[20][1]};
  for (int i = 0; i < 4; ++i) add_quad(tris, {3.0 + i, 0, 0}, {1, 0, 0}, {0, 1, 0});
  tris.push_back(Tri{Vec3d{5, 5, 5}, Vec3d{5, 5, 5}, Vec3d{6, 5, 5}});
  tris.push_back(Tri{Vec3d{0.0, 4, 0}, Vec3d{1, 4, 0}, Vec3d{0.0, 5, 0}});
  tris.push_back(Tri{Vec3d{-0.0, 4, 0}, Vec3d{-1, 5, 0}, Vec3d{-0.0, 5, 0}});
  return tris;
}

void check_same_edges(const OccluderEdges& a, const OccluderEdges& b) {
  CHECK(a.edge_of == b.edge_of);
  CHECK(a.direction_of == b.direction_of);
  CHECK(a.endpoints == b.endpoints);
  CHECK(a.first_incident == b.first_incident);
  CHECK(a.incident == b.incident);
  CHECK(a.has_open_edge == b.has_open_edge);
}

}  // namespace

TEST_CASE("occluder edges: each side's edge holds exactly the sides with its endpoints, numbered as the triangles first name them") {
  const OccluderTriangles triangles = triangles_of(awkward_mesh());
  const OccluderEdges edges = edges_of(triangles);
  const std::size_t n = triangles.size();
  auto ends = [&](std::uint32_t code) {  // the side's endpoints, lexicographic, and its direction
    const Vec3d& x = triangles.corners[code / 3][code % 3];
    const Vec3d& y = triangles.corners[code / 3][(code % 3 + 1) % 3];
    const bool forward = !lexicographic_less(y, x);
    return std::tuple{forward ? x : y, forward ? y : x, forward ? 1 : -1};
  };
  std::uint32_t next_edge = 0;
  int non_manifold = 0, open_triangles = 0, joined_signed_zeros = 0;
  for (std::uint32_t code = 0; code < 3 * n; ++code) {
    const auto [a, b, direction] = ends(code);
    std::vector<std::uint32_t> same;  // ascending
    for (std::uint32_t other = 0; other < 3 * n; ++other)
      if (std::get<0>(ends(other)) == a && std::get<1>(ends(other)) == b) same.push_back(other);
    const std::uint32_t e = edges.edge_of[code / 3][code % 3];
    // Edges are numbered in the order the triangles first name them: a side that is its edge's
    // first takes the next number.
    if (same.front() == code) CHECK(e == next_edge++);
    REQUIRE(e < edges.size());
    CHECK(edges.direction_of[code / 3][code % 3] == direction);
    CHECK(edges.endpoints[e][0] == a);
    CHECK(edges.endpoints[e][1] == b);
    const std::vector<std::uint32_t> incident(edges.incident.begin() + edges.first_incident[e],
                                              edges.incident.begin() + edges.first_incident[e + 1]);
    CHECK(incident == same);
    non_manifold += same.size() > 2;
    for (std::uint32_t c : same) joined_signed_zeros += std::signbit(std::get<0>(ends(c)).x) != std::signbit(a.x);
  }
  CHECK(next_edge == edges.size());
  CHECK(non_manifold > 0);
  CHECK(joined_signed_zeros > 0);
  // A triangle has an open edge when one of its edges is not two sides of opposite directions.
  for (std::uint32_t t = 0; t < n; ++t) {
    bool open = false;
    for (int j = 0; j < 3; ++j) {
      const std::uint32_t e = edges.edge_of[t][j];
      int balance = 0;
      for (std::uint32_t k = edges.first_incident[e]; k < edges.first_incident[e + 1]; ++k)
        balance += edges.direction_of[edges.incident[k] / 3][edges.incident[k] % 3];
      open = open || edges.first_incident[e + 1] - edges.first_incident[e] != 2 || balance != 0;
    }
    CHECK(static_cast<bool>(edges.has_open_edge[t]) == open);
    open_triangles += open;
  }
  CHECK(open_triangles > 8);
  CHECK(open_triangles < static_cast<int>(n) / 4);
}

TEST_CASE("the occluder BVH and edges built on two threads equal those built on one") {
  // Enough triangles that the BVH builds its top subtrees as parallel tasks (2 x 16384).
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> pos(-3, 3), off(-0.05, 0.05), height(0.2, 2.8);
  std::vector<Tri> tris = icosphere({0, 0, 1.5}, 1, 5);
  while (tris.size() < 50000) {
    const Vec3d c{pos(rng), pos(rng), height(rng)};
    tris.push_back({c + Vec3d{off(rng), off(rng), off(rng)}, c + Vec3d{off(rng), off(rng), off(rng)},
                    c + Vec3d{off(rng), off(rng), off(rng)}});
  }
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const OccluderBvh one = make_bvh(tris);
  omp_set_num_threads(2);
  const OccluderBvh two = make_bvh(tris), brute = make_bvh(tris, true);
  omp_set_num_threads(threads);
  CHECK(one.node_count() == two.node_count());
  bool same_order = true;
  for (std::size_t t = 0; t < tris.size(); ++t)
    same_order = same_order && one.triangles().ids[t].triangle == two.triangles().ids[t].triangle;
  CHECK(same_order);
  check_same_edges(one.edges(), two.edges());
  check_same_edges(edges_of(one.triangles()), two.edges());
  // The same answers, and the brute force's, to volume and silhouette queries.
  const PreparedAreaLight<double> light = prepare_area_light(AreaLight<double>{square_light(1.5, 3), false});
  std::uniform_real_distribution<double> floor(-4, 4);
  std::vector<std::uint32_t> a, b, c;
  std::vector<std::uint8_t> a_in, b_in;
  std::size_t found = 0;
  for (int i = 0; i < 100; ++i) {
    const Vec3d p{floor(rng), floor(rng), 0};
    const AreaView<double> view = make_area_view(light, p);
    ClipPolygon<double> horizon;
    clip_to_horizon(light, view, Vec3d{0, 0, 1}, horizon);
    const ConvexVolume volume = area_shadow_volume(light, view, horizon, p);
    one.triangles_in_volume(volume, p, a);
    two.triangles_in_volume(volume, p, b);
    brute.triangles_in_volume(volume, p, c);
    CHECK(a == b);
    CHECK(b == c);
    found += a.size();
    const AreaSlab slab = area_slab(light, view, p);
    const HalfSpace inside[2] = {slab.beyond_light, slab.before_p};
    one.silhouette_candidates(volume, inside, 2, p, a, a_in);
    two.silhouette_candidates(volume, inside, 2, p, b, b_in);
    CHECK(a == b);
    CHECK(a_in == b_in);
  }
  CHECK(found > 1000);
}
