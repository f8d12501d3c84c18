// Tests of homogeneous clipping (clip.h): the near plane cut lands on the plane, the polygon keeps
// its winding, shared edges are cut at bit-identical points whatever the traversal direction.
#include <doctest/doctest.h>

#include <cmath>

#include "raster/clip.h"

using namespace vlit;
using namespace vlit::raster;

namespace {

ClipVertex cv(double x, double y, double z, double w, double r = 0) { return {{x, y, z, w}, {r, 0, 0}}; }

double signed_area_ndc(const std::array<ClipVertex, kMaxClipVertices>& p, int n) {
  double a = 0;
  for (int i = 0; i < n; ++i) {
    const Vec4d& u = p[i].position;
    const Vec4d& v = p[(i + 1) % n].position;
    a += (u.x / u.w) * (v.y / v.w) - (v.x / v.w) * (u.y / u.w);
  }
  return a;
}

}  // namespace

TEST_CASE("clip: a triangle with one vertex behind the near plane becomes a quad on the plane") {
  const ClipPlanes planes = make_clip_planes(100, 100, false);
  // Perspective-like clip coordinates: w = distance, near plane z = -w.
  const ClipVertex a = cv(-1, -1, 1, 2, 0), b = cv(1, -1, 1, 2, 0), c = cv(0, 1, -5, -3, 1);  // c behind
  std::array<ClipVertex, kMaxClipVertices> out;
  const int n = clip_triangle(a, b, c, planes, out);
  REQUIRE(n == 4);
  int on_plane = 0;
  for (int i = 0; i < n; ++i) {
    CHECK(out[i].position.w > 0);
    CHECK(out[i].position.z + out[i].position.w >= -1e-12);
    if (std::abs(out[i].position.z + out[i].position.w) < 1e-12) {
      ++on_plane;
      CHECK(out[i].color.x > 0);  // colour interpolated towards c
      CHECK(out[i].color.x < 1);
    }
  }
  CHECK(on_plane == 2);
  // The winding is kept: the visible polygon faces the way the whole triangle faces. The facing
  // of a triangle with a vertex behind the eye is the sign of the homogeneous determinant
  // det[x y w] of its clip-space vertices (Olano & Greer 1997), which needs no clipping.
  const auto det_xyw = [](const Vec4d& u, const Vec4d& v, const Vec4d& t) {
    return u.x * (v.y * t.w - t.y * v.w) - u.y * (v.x * t.w - t.x * v.w) + u.w * (v.x * t.y - t.x * v.y);
  };
  const double facing = det_xyw(a.position, b.position, c.position);
  REQUIRE(facing != 0);
  CHECK((facing > 0) == (signed_area_ndc(out, n) > 0));
  // And reversing the input reverses the output.
  const int n_reversed = clip_triangle(c, b, a, planes, out);
  REQUIRE(n_reversed == 4);
  CHECK((facing > 0) == (signed_area_ndc(out, n_reversed) < 0));
}

TEST_CASE("clip: fully outside is dropped, fully inside is untouched") {
  const ClipPlanes planes = make_clip_planes(64, 48, true);
  std::array<ClipVertex, kMaxClipVertices> out;
  CHECK(clip_triangle(cv(0, 0, -5, -1), cv(1, 0, -5, -1), cv(0, 1, -5, -1), planes, out) == 0);  // behind
  CHECK(clip_triangle(cv(0, 0, 5, 1), cv(1, 0, 5, 1), cv(0, 1, 5, 1), planes, out) == 0);        // beyond far
  const ClipVertex a = cv(0.1, 0.2, 0.3, 1), b = cv(0.5, 0.2, 0.3, 1), c = cv(0.1, 0.7, 0.1, 1);
  REQUIRE(clip_triangle(a, b, c, planes, out) == 3);
  CHECK(out[0].position == a.position);
  CHECK(out[1].position == b.position);
  CHECK(out[2].position == c.position);
}

TEST_CASE("clip: two triangles sharing an edge cut it at bit-identical points") {
  const ClipPlanes planes = make_clip_planes(100, 100, true);
  // Shared edge p -> q crosses the near plane; the triangles traverse it in opposite directions.
  const ClipVertex p = cv(-0.3, 0.2, 0.5, 1.5), q = cv(0.4, -0.1, -7, -2.5);
  const ClipVertex left = cv(-1, 1, 0.5, 1.5), right = cv(1, -1, 0.2, 1.2);
  std::array<ClipVertex, kMaxClipVertices> out1, out2;
  const int n1 = clip_triangle(p, q, left, planes, out1);
  const int n2 = clip_triangle(q, p, right, planes, out2);
  REQUIRE(n1 >= 3);
  REQUIRE(n2 >= 3);
  // The cut point of the shared edge on the near plane.
  const auto find_cut = [&](const std::array<ClipVertex, kMaxClipVertices>& o, int n, const Vec4d& other) {
    for (int i = 0; i < n; ++i) {
      const Vec4d& v = o[i].position;
      if (v == p.position || v == other) continue;
      // On the line p + t (q - p)?
      const double t = (v.w - p.position.w) / (q.position.w - p.position.w);
      const Vec4d on = p.position + (q.position - p.position) * t;
      if (std::abs(on.x - v.x) < 1e-9 && std::abs(on.y - v.y) < 1e-9 && std::abs(on.z - v.z) < 1e-9) return v;
    }
    return Vec4d{NAN, NAN, NAN, NAN};
  };
  const Vec4d cut1 = find_cut(out1, n1, left.position), cut2 = find_cut(out2, n2, right.position);
  REQUIRE(is_finite(cut1));
  CHECK(cut1 == cut2);  // bitwise equal, not merely close
}
