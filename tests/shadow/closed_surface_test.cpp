// is_closed_surface against its definition checked pair by pair: every directed edge, by corner
// position, is met by exactly one reversed edge, none repeats, no side has zero length.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

bool closed_by_pairs(const std::vector<Tri>& tris) {
  if (tris.empty()) return false;
  for (const Tri& t : tris)
    for (int e = 0; e < 3; ++e) {
      const Vec3d& a = t[e];
      const Vec3d& b = t[(e + 1) % 3];
      if (a == b) return false;
      int same = 0, reversed = 0;
      for (const Tri& u : tris)
        for (int f = 0; f < 3; ++f) {
          same += u[f] == a && u[(f + 1) % 3] == b;
          reversed += u[f] == b && u[(f + 1) % 3] == a;
        }
      if (same != 1 || reversed != 1) return false;
    }
  return true;
}

}  // namespace

TEST_CASE("closed surfaces: is_closed_surface agrees with the pair-by-pair definition") {
  std::vector<Tri> box;
  add_box(box, Vec3d{0, -0.5, 0.25}, Vec3d{1, 0.5, 1});
  std::vector<std::pair<std::string, std::vector<Tri>>> cases;
  cases.push_back({"box", box});
  cases.push_back({"icosphere", icosphere({0, 0, 0}, 1, 2)});
  std::vector<Tri> signed_zeros = box;  // the same positions, some named with -0
  for (std::size_t i = 0; i < signed_zeros.size(); i += 2)
    for (Vec3d& c : signed_zeros[i])
      if (c.x == 0) c.x = -0.0;
  cases.push_back({"box with -0 corners", signed_zeros});
  std::vector<Tri> two = box;  // two separate boxes: closed together
  add_box(two, Vec3d{2, 2, 2}, Vec3d{3, 3, 3});
  cases.push_back({"two boxes", two});
  std::vector<Tri> missing = box;
  missing.pop_back();
  cases.push_back({"a face missing", missing});
  std::vector<Tri> flipped = box;
  std::swap(flipped[3][1], flipped[3][2]);
  cases.push_back({"a face wound the other way", flipped});
  std::vector<Tri> doubled = box;
  doubled.push_back(box[5]);
  doubled.push_back({box[5][0], box[5][2], box[5][1]});
  cases.push_back({"a face doubled, both ways", doubled});
  std::vector<Tri> sliver = box;
  sliver.push_back({box[0][0], box[0][0], box[0][1]});
  cases.push_back({"a zero-length side", sliver});
  std::vector<Tri> not_finite = box;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  not_finite[4][0] = {nan, 0, 0};
  cases.push_back({"a corner not finite", not_finite});
  cases.push_back({"nothing", {}});
  int closed = 0, open = 0;
  for (const auto& item : cases) {
    // Named, not bound: CAPTURE's lambda captures it (clang 14 does not capture structured bindings).
    const auto& name = item.first;
    const auto& tris = item.second;
    CAPTURE(name);
    const ScenePrimitive prim = primitive_of(tris);
    const bool expected = closed_by_pairs(tris);
    CHECK(is_closed_surface({&prim}) == expected);
    (expected ? closed : open) += 1;
  }
  CHECK(closed == 4);
  CHECK(open == 6);
  // Split into two primitives (a mesh split by material), closed together only.
  const ScenePrimitive top = primitive_of({box.begin(), box.begin() + 6}), rest = primitive_of({box.begin() + 6, box.end()});
  CHECK(is_closed_surface({&top, &rest}));
  CHECK_FALSE(is_closed_surface({&top}));
  // An index out of range: not closed.
  ScenePrimitive bad = primitive_of(box);
  bad.triangles[7] = static_cast<std::uint32_t>(bad.positions.size());
  CHECK_FALSE(is_closed_surface({&bad}));
}
