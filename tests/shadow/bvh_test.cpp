// The BVH against the brute-force path: identical answers for shadow rays, volume queries and
// whole shadowed evaluations on a random triangle soup.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "shadow_test_util.h"
#include "shadow/area_visibility.h"

using namespace vlit;
using namespace vlit::test;

namespace {

std::vector<Tri> random_soup(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(-3, 3), off(-0.4, 0.4), height(0.2, 2.8);
  std::vector<Tri> tris;
  for (int i = 0; i < count; ++i) {
    const Vec3d c{pos(rng), pos(rng), height(rng)};
    tris.push_back({c + Vec3d{off(rng), off(rng), off(rng)}, c + Vec3d{off(rng), off(rng), off(rng)},
                    c + Vec3d{off(rng), off(rng), off(rng)}});
  }
  return tris;
}

// The volume between a floor point p (normal +z) and the light.
ConvexVolume volume_to_light(const PreparedAreaLight<double>& light, const Vec3d& p) {
  const AreaView<double> view = make_area_view(light, p);
  ClipPolygon<double> horizon;
  clip_to_horizon(light, view, Vec3d{0, 0, 1}, horizon);
  return area_shadow_volume(light, view, horizon, p);
}

// Floor points at random in [-4, 4]^2 (drawn from rng), each with its volume to the light.
struct FloorPoint {
  Vec3d p;
  ConvexVolume volume;
};
std::vector<FloorPoint> floor_points(const PreparedAreaLight<double>& light, int count, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(-4, 4);
  std::vector<FloorPoint> out;
  for (int i = 0; i < count; ++i) {
    const Vec3d p{pos(rng), pos(rng), 0};
    out.push_back({p, volume_to_light(light, p)});
  }
  return out;
}

}  // namespace

TEST_CASE("BVH and brute force agree on shadow rays and volume queries") {
  const std::vector<Tri> tris = random_soup(3000, 11);
  const OccluderBvh bvh = make_bvh(tris), brute = make_bvh(tris, true);
  CHECK(bvh.node_count() > 1);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pos(-4, 4);
  int blocked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3d a{pos(rng), pos(rng), 0}, b{pos(rng), pos(rng), 3.5};
    const bool x = bvh.segment_occluded(a, b, a), y = brute.segment_occluded(a, b, a);
    CHECK(x == y);
    blocked += x;
  }
  CHECK(blocked > 100);
  CHECK(blocked < 1900);
  const PreparedAreaLight<double> light = prepare_area_light(AreaLight<double>{square_light(1.5, 3), false});
  std::vector<std::uint32_t> a, b;
  std::size_t found = 0;
  for (const auto& [p, volume] : floor_points(light, 200, rng)) {
    bvh.triangles_in_volume(volume, p, a);
    brute.triangles_in_volume(volume, p, b);
    CHECK(a == b);
    found += a.size();
  }
  CHECK(found > 0);
}

TEST_CASE("shadowed lights are identical with the BVH on and off") {
  const std::vector<Tri> tris = random_soup(400, 3);
  const OccluderBvh bvh = make_bvh(tris), brute = make_bvh(tris, true);
  std::vector<LightSource> lights{area_source(square_light(1.5, 3.2)), linear_source({-2, 0, 3.2}, {2, 0.5, 3.3}, 2)};
  LightSource point;
  point.position = {0.5, 0.5, 3.5};
  lights.push_back(point);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> pos(-3, 3);
  int partly = 0;
  for (const LightSource& source : lights) {
    const PreparedLight<double> light = prepare_light<double>(source);
    for (int i = 0; i < 60; ++i) {
      const ShadingPoint<double> sp = make_shading_point(Vec3d{pos(rng), pos(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 6}, 10.0);
      const ShadeOptions o = options_with(SpecularMethod::kPeak);
      const Response<double> x = shade_shadowed(light, sp, o, bvh), y = shade_shadowed(light, sp, o, brute);
      CHECK(x.diffuse == y.diffuse);
      CHECK(x.specular == y.specular);
      const double open = shade(light, sp, o).diffuse;
      partly += x.diffuse > 0 && x.diffuse < open;
    }
  }
  CHECK(partly > 10);  // the comparison covered real penumbrae
}

TEST_CASE("the silhouette search returns its triangles ascending, and flags only those inside the slab") {
  // Triangles between the light and the floor, and triangles that cross the light's plane and the
  // plane just above P (the slab's planes), so that both flags occur.
  std::vector<Tri> tris = random_soup(3000, 21);
  const std::vector<Tri> tall = random_soup(300, 22);
  for (const Tri& t : tall) tris.push_back({t[0] + Vec3d{0, 0, 1.5}, t[1] - Vec3d{0, 0, 2.4}, t[2]});
  const OccluderBvh bvh = make_bvh(tris), brute = make_bvh(tris, true);
  const PreparedAreaLight<double> light = prepare_area_light(AreaLight<double>{square_light(1.5, 3), false});
  std::mt19937_64 rng(7);
  std::vector<std::uint32_t> found, all;
  std::vector<std::uint8_t> in_slab, brute_in_slab;
  std::size_t flagged = 0, unflagged = 0;
  for (const auto& [p, volume] : floor_points(light, 200, rng)) {
    const AreaSlab slab = area_slab(light, make_area_view(light, p), p);
    const HalfSpace inside[2] = {slab.beyond_light, slab.before_p};
    bvh.silhouette_candidates(volume, inside, 2, p, found, in_slab);
    brute.silhouette_candidates(volume, inside, 2, p, all, brute_in_slab);
    REQUIRE(in_slab.size() == found.size());
    CHECK(std::is_sorted(found.begin(), found.end()));
    CHECK(std::adjacent_find(found.begin(), found.end()) == found.end());
    CHECK(std::includes(all.begin(), all.end(), found.begin(), found.end()));
    for (std::size_t k = 0; k < found.size(); ++k) {
      if (!in_slab[k]) {
        ++unflagged;
        continue;
      }
      ++flagged;
      for (const Vec3d& c : bvh.triangles().corners[found[k]])
        for (const HalfSpace& h : inside) CHECK(h.signed_distance(c) > 0);
    }
  }
  CHECK(flagged > 1000);
  CHECK(unflagged > 100);
}

TEST_CASE("leaves_reached: deciding runs of leaves by their block keeps exactly the leaves the leaf tests keep") {
  std::vector<Tri> tris = random_soup(3000, 23);
  const OccluderBvh bvh = make_bvh(tris);
  const PreparedAreaLight<double> light = prepare_area_light(AreaLight<double>{square_light(1.5, 3), false});
  // Every leaf of the tree: a search of a volume that holds everything, from a point so vague
  // (radius 1e9) that no subtree faces it uniformly.
  ConvexVolume everything;
  for (const Tri& t : tris)
    for (const Vec3d& c : t) everything.box.grow(c);
  std::vector<std::uint32_t> leaves;
  bvh.silhouette_leaves(everything, nullptr, 0, Vec3d{0, 0, 0}, 1e9, leaves);
  REQUIRE(leaves.size() > 500);
  OccluderBvh::LeafBounds bounds;
  bvh.leaf_bounds(leaves, bounds);
  REQUIRE(bounds.leaf.size() == leaves.size());
  REQUIRE(bounds.block.size() == (leaves.size() + OccluderBvh::kLeafBlock - 1) / OccluderBvh::kLeafBlock);
  // The same leaves with blocks that decide nothing (a ball far wider than the scene straddles
  // every plane through it): each leaf is tested alone.
  OccluderBvh::LeafBounds alone = bounds;
  for (OccluderBvh::Bounds& block : alone.block) {
    block.box = everything.box;
    block.ball = {Vec3d{0, 0, 0}, 1e6, 0};
  }
  std::mt19937_64 rng(9);
  std::vector<std::uint32_t> by_blocks, by_leaves;
  std::size_t kept = 0, dropped = 0;
  for (const auto& [p, volume] : floor_points(light, 300, rng)) {
    bvh.leaves_reached(bounds, volume, by_blocks);
    bvh.leaves_reached(alone, volume, by_leaves);
    CHECK(by_blocks == by_leaves);
    // No leaf with a triangle that reaches the volume is dropped.
    for (std::size_t k = 0; k < leaves.size(); ++k) {
      const auto [first, end] = bvh.leaf_triangles(leaves[k]);
      bool reaches = false;
      for (std::uint32_t t = first; t < end && !reaches; ++t) reaches = bvh.near_volume(t, volume);
      if (reaches) CHECK(std::binary_search(by_blocks.begin(), by_blocks.end(), static_cast<std::uint32_t>(k)));
    }
    kept += by_blocks.size();
    dropped += leaves.size() - by_blocks.size();
  }
  CHECK(kept > 30000);  // about 37 % of the leaves per point
  CHECK(dropped > 30000);
}
