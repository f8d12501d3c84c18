// The silhouette visibility of area lights (src/shadow/area_silhouette.h) against the
// triangle-by-triangle cutting (area_visibility.h), which the other shadow tests hold to shadow
// rays and to exact symmetric answers: the same light on random soups, refined closed spheres,
// boxes in random orientations, a bumpy surface shadowing itself (occluders crossing the slab
// next to P) and a mesh with T-junctions. Each case also checks that the silhouette path answered
// (not its fallback), so a broken fast path cannot hide behind the reference.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <random>

#include "load/load_scene.h"
#include "shadow/area_silhouette.h"
#include "shadow/shadowed_vertices.h"
#include "shadow/sweep_axes.h"
#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

struct Agreement {
  double diffuse = 0, specular = 0;  // largest difference / unshadowed value
  int shadowed = 0, cases = 0;
};

// Both methods at one point; differences relative to the unshadowed value.
void compare(const PreparedLight<double>& light, const ShadingPoint<double>& sp, const OccluderBvh& bvh,
             SpecularMethod method, Agreement& out) {
  ShadeOptions fast = options_with(method), cuts = options_with(method);
  cuts.area_shadows = AreaShadowMethod::kTriangleCuts;
  const Response<double> a = shade_shadowed(light, sp, fast, bvh), b = shade_shadowed(light, sp, cuts, bvh);
  const Response<double> open = shade(light, sp, fast);
  record_agreement(a, b, open, out.diffuse, out.specular);
  out.shadowed += b.diffuse < open.diffuse * (1 - 1e-9);
  ++out.cases;
}

// Asks the silhouette path at each point the light reaches; `scratch` counts the queries and
// those it left undecided (for the triangle cuts).
void ask_silhouettes(const PreparedAreaLight<double>& light, const std::vector<ShadingPoint<double>>& points,
                     const OccluderBvh& bvh, AreaSilhouetteScratch& scratch) {
  for (const ShadingPoint<double>& sp : points) {
    const AreaView<double> view = make_area_view(light, sp.p);
    if (!view.lit) continue;
    ClipPolygon<double> horizon;
    clip_to_horizon(light, view, sp.n, horizon);
    if (horizon.count < 3) continue;
    visible_area_by_silhouettes(light, view, horizon, sp.p, bvh, scratch);
  }
}

// How often the silhouette path decided by itself at these points (1 = always).
double decided_fraction(const PreparedAreaLight<double>& light, const std::vector<ShadingPoint<double>>& points,
                        const OccluderBvh& bvh) {
  AreaSilhouetteScratch scratch;
  ask_silhouettes(light, points, bvh, scratch);
  return scratch.queries ? 1 - static_cast<double>(scratch.undecided) / scratch.queries : 1.0;
}

const PreparedAreaLight<double>& area_of(const PreparedLight<double>& l) {
  return std::get<PreparedAreaLight<double>>(l.kernel);
}

}  // namespace

TEST_CASE("silhouettes = triangle cuts: random soups between a panel and a floor") {
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(0.7, 2)));
  std::mt19937_64 rng(1505);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  Agreement agree;
  double decided = 0;
  const int trials = 60;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<Tri> tris;
    add_random_triangles(tris, rng, 5 + static_cast<int>(rng() % 40));
    const OccluderBvh bvh = make_bvh(tris);
    std::vector<ShadingPoint<double>> points;
    for (int k = 0; k < 12; ++k)
      points.push_back(make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0.3, -0.2, 3}, 20.0));
    for (const auto& sp : points)
      for (SpecularMethod method : {SpecularMethod::kNone, SpecularMethod::kExact, SpecularMethod::kPeak}) {
        INFO("trial " << trial);
        compare(panel, sp, bvh, method, agree);
      }
    decided += decided_fraction(area_of(panel), points, bvh);
  }
  MESSAGE("soups: " << agree.shadowed << " of " << agree.cases << " shadowed; largest difference diffuse "
                    << agree.diffuse << ", specular " << agree.specular << "; decided " << decided / trials);
  CHECK(agree.shadowed > agree.cases / 4);
  CHECK(agree.diffuse <= 1e-9);
  CHECK(agree.specular <= 1e-7);
  CHECK(decided / trials >= 0.95);
}

TEST_CASE("silhouettes = triangle cuts: refined closed spheres and rotated boxes") {
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(1, 3)));
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (int levels = 0; levels <= 3; ++levels) {
    const std::vector<Tri> sphere = icosphere({0.1, -0.05, 1.4}, 0.55, levels);
    const OccluderBvh bvh = make_bvh(sphere);
    Agreement agree;
    std::vector<ShadingPoint<double>> points;
    for (int k = 0; k < 24; ++k)
      points.push_back(make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0));
    for (const auto& sp : points) compare(panel, sp, bvh, SpecularMethod::kExact, agree);
    const double decided = decided_fraction(area_of(panel), points, bvh);
    MESSAGE("sphere, " << sphere.size() << " triangles: " << agree.shadowed << " of " << agree.cases
                       << " shadowed; diffuse " << agree.diffuse << ", specular " << agree.specular << "; decided "
                       << decided);
    CHECK(agree.shadowed > 4);
    CHECK(agree.diffuse <= 1e-9);
    CHECK(agree.specular <= 1e-7);
    CHECK(decided == 1.0);
  }
  Agreement boxes;
  for (int trial = 0; trial < 20; ++trial) {
    const OccluderBvh bvh = make_bvh(turned_box(rng));
    for (int k = 0; k < 8; ++k) {
      const ShadingPoint<double> sp = make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{1, 0, 4}, 30.0);
      compare(panel, sp, bvh, SpecularMethod::kExact, boxes);
    }
  }
  MESSAGE("boxes: " << boxes.shadowed << " of " << boxes.cases << " shadowed; diffuse " << boxes.diffuse
                    << ", specular " << boxes.specular);
  CHECK(boxes.shadowed > 20);
  CHECK(boxes.diffuse <= 1e-9);
  CHECK(boxes.specular <= 1e-7);
}

TEST_CASE("silhouettes = triangle cuts: a bumpy surface shadowing its own vertices") {
  // A height field z = f(x, y) lit from low on one side by a steep two-sided panel: occluders
  // cross the slab next to P and the triangles at P are skipped (no acne), the hard case of
  // self-shadowing.
  const PreparedLight<double> panel = prepare_light<double>(
      area_source({{2.4, -0.6, 0.3}, {2.4, 0.6, 0.3}, {2.7, 0.6, 1.2}, {2.7, -0.6, 1.2}}, true));
  const BumpySurface surface = bumpy_surface(14, 0.4);
  const OccluderBvh bvh = make_bvh(surface.tris);
  const std::vector<ShadingPoint<double>>& points = surface.points;
  Agreement agree;
  for (const auto& sp : points) compare(panel, sp, bvh, SpecularMethod::kExact, agree);
  const double decided = decided_fraction(area_of(panel), points, bvh);
  MESSAGE("bumpy surface: " << agree.shadowed << " of " << agree.cases << " shadowed; diffuse " << agree.diffuse
                            << ", specular " << agree.specular << "; decided " << decided);
  CHECK(agree.shadowed > 10);
  CHECK(agree.diffuse <= 1e-9);
  CHECK(agree.specular <= 1e-7);
  CHECK(decided >= 0.95);
}

// Pieces as (u, v) in the view's frame, and whether one is a simple polygon turning counter-
// clockwise in that frame (no two of its edges that do not share a corner meet).
std::vector<std::pair<double, double>> piece_uv(const LightPieces& pieces, std::size_t i, const AreaView<double>& view) {
  std::vector<std::pair<double, double>> uv;
  for (int k = pieces.start[i]; k < pieces.start[i + 1]; ++k)
    uv.push_back({dot(view.u, pieces.points[k]), dot(view.v, pieces.points[k])});
  return uv;
}

double signed_twice_area(const std::vector<std::pair<double, double>>& uv) {
  double sum = 0;
  for (std::size_t k = 0; k < uv.size(); ++k) {
    const auto& [ax, ay] = uv[k];
    const auto& [bx, by] = uv[(k + 1) % uv.size()];
    sum += ax * by - bx * ay;
  }
  return sum;
}

bool simple_polygon(const std::vector<std::pair<double, double>>& uv) {
  const std::size_t n = uv.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // they share corner 0
      const auto& [ax, ay] = uv[i];
      const auto& [bx, by] = uv[(i + 1) % n];
      const auto& [cx, cy] = uv[j];
      const auto& [dx, dy] = uv[(j + 1) % n];
      const int c = orient2_sign(ax, ay, bx, by, cx, cy), d = orient2_sign(ax, ay, bx, by, dx, dy);
      const int a = orient2_sign(cx, cy, dx, dy, ax, ay), b = orient2_sign(cx, cy, dx, dy, bx, by);
      if (c * d <= 0 && a * b <= 0 && (c != 0 || d != 0 || a != 0 || b != 0)) return false;
    }
  return true;
}

TEST_CASE("silhouettes: pieces merged along chains cover what the trapezoids cover") {
  // SilhouettePieces::kChains continues a piece where the segment bounding it ends and the next
  // one of a silhouette starts: refined spheres, whose silhouettes are chains of many short
  // edges, seen from tilted floor points, with the light's horizon cut. The same answer, the same
  // diffuse (eq. 9 over the pieces) and area, simple counter-clockwise pieces within the size
  // limit, and far fewer of them.
  // Also from behind a two-sided light (the scene mirrored across its plane), where the pieces
  // turn the other way in the view's frame, as the light does.
  std::mt19937_64 rng(2027);
  std::uniform_real_distribution<double> u(-1.2, 1.2), tilt(-0.6, 0.6);
  long compared = 0, trapezoids = 0, chains = 0, largest = 0;
  double diffuse = 0, area = 0;
  for (bool behind : {false, true}) {
    const PreparedLight<double> light = prepare_light<double>(area_source(square_light(1, 3), behind));
    const PreparedAreaLight<double>& panel = area_of(light);
    const double side = behind ? -1 : 1;  // z -> 3 - side (3 - z) mirrors the scene behind the light
    auto at_z = [&](double z) { return 3 - side * (3 - z); };
    for (int levels : {1, 2, 3, 4}) {
      const OccluderBvh bvh = make_bvh(icosphere({0.1, -0.05, at_z(1.4)}, 0.55, levels));
      for (int k = 0; k < 40; ++k) {
        const ShadingPoint<double> sp = make_shading_point(Vec3d{u(rng), u(rng), at_z(0)},
                                                           normalize(Vec3d{tilt(rng), tilt(rng), side}),
                                                           Vec3d{0, 0, at_z(4)}, 8.0);
        const AreaView<double> view = make_area_view(panel, sp.p);
        ClipPolygon<double> horizon;
        clip_to_horizon(panel, view, sp.n, horizon);
        if (!view.lit || horizon.count < 3) continue;
        AreaSilhouetteScratch by_trapezoids, by_chains;
        const SilhouetteVisibility a = visible_area_by_silhouettes(panel, view, horizon, sp.p, bvh, by_trapezoids,
                                                                   nullptr, SilhouettePieces::kTrapezoids);
        const SilhouetteVisibility b = visible_area_by_silhouettes(panel, view, horizon, sp.p, bvh, by_chains, nullptr,
                                                                   SilhouettePieces::kChains);
        REQUIRE(a == b);
        if (a != SilhouetteVisibility::kPieces) continue;
        ++compared;
        trapezoids += static_cast<long>(by_trapezoids.pieces.size());
        chains += static_cast<long>(by_chains.pieces.size());
        // The light's own turn in the view's frame: every piece turns the same way.
        std::vector<std::pair<double, double>> light_uv;
        for (int i = 0; i < horizon.count; ++i) light_uv.push_back({dot(view.u, horizon.d[i]), dot(view.v, horizon.d[i])});
        const double turn = signed_twice_area(light_uv) > 0 ? 1 : -1;
        const double open = area_diffuse_contour(panel, view, horizon, sp.n);
        double diffuse_a = 0, diffuse_b = 0, area_a = 0, area_b = 0;
        ClipPolygon<double> piece;
        auto load = [&](const LightPieces& pieces, std::size_t i) -> const ClipPolygon<double>& {
          piece.count = pieces.start[i + 1] - pieces.start[i];
          std::copy(pieces.points.begin() + pieces.start[i], pieces.points.begin() + pieces.start[i + 1], piece.d.begin());
          return piece;
        };
        for (std::size_t i = 0; i < by_trapezoids.pieces.size(); ++i) {
          diffuse_a += area_diffuse_contour(panel, view, load(by_trapezoids.pieces, i), sp.n);
          area_a += turn * signed_twice_area(piece_uv(by_trapezoids.pieces, i, view));
        }
        for (std::size_t i = 0; i < by_chains.pieces.size(); ++i) {
          diffuse_b += area_diffuse_contour(panel, view, load(by_chains.pieces, i), sp.n);
          const std::vector<std::pair<double, double>> uv = piece_uv(by_chains.pieces, i, view);
          area_b += turn * signed_twice_area(uv);
          largest = std::max(largest, static_cast<long>(uv.size()));
          INFO((behind ? "behind" : "in front") << ", level " << levels << ", point " << k << ", piece " << i);
          CHECK(uv.size() <= static_cast<std::size_t>(kMaxChainPiece + 4));
          CHECK(turn * signed_twice_area(uv) > 0);
          CHECK(simple_polygon(uv));
        }
        diffuse = std::max(diffuse, std::abs(diffuse_a - diffuse_b) / open);
        area = std::max(area, std::abs(area_a - area_b) / (2 * panel.area));
      }
    }
  }
  MESSAGE("chains: " << compared << " partly hidden points, " << trapezoids << " trapezoids, " << chains
                     << " chain pieces (largest " << largest << " corners); diffuse " << diffuse << ", area " << area);
  CHECK(compared >= 120);
  CHECK(diffuse <= 1e-12);
  CHECK(area <= 1e-12);
  CHECK(3 * chains < trapezoids);
  // Who gets chains: the diffuse alone, of a polygon, with no crease wedges to cut.
  CHECK(silhouette_pieces_for(options_with(SpecularMethod::kNone), false, false) == SilhouettePieces::kChains);
  for (SpecularMethod method : {SpecularMethod::kExact, SpecularMethod::kPeak, SpecularMethod::kNeighborhood})
    CHECK(silhouette_pieces_for(options_with(method), false, false) == SilhouettePieces::kTrapezoids);
  CHECK(silhouette_pieces_for(options_with(SpecularMethod::kNone), true, false) == SilhouettePieces::kTrapezoids);
  CHECK(silhouette_pieces_for(options_with(SpecularMethod::kNone), false, true) == SilhouettePieces::kTrapezoids);

  // Two triangles, one ending and the other starting on one line of constant v (their corners
  // project to the same bits): the visible part's left side passes from one to the other there,
  // but along that line, not at one point. A piece must not continue from the first's side to the
  // second's.
  const PreparedLight<double> light = prepare_light<double>(area_source(square_light(1, 3)));
  const PreparedAreaLight<double>& panel = area_of(light);
  const SweepAxes axes = sweep_axes(panel);
  auto at = [&](double a, double b) { return axes.u * a + axes.v * b + Vec3d{0, 0, 1.5}; };
  const OccluderBvh steps = make_bvh({{at(-0.3, -0.4), at(0.1, -0.15), at(0.1, 0)}, {at(-0.1, 0), at(-0.1, 0.4), at(-0.5, 0.4)}});
  const ShadingPoint<double> sp = make_shading_point(Vec3d{0, 0, 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0);
  const AreaView<double> view = make_area_view(panel, sp.p);
  ClipPolygon<double> horizon;
  clip_to_horizon(panel, view, sp.n, horizon);
  AreaSilhouetteScratch by_trapezoids, by_chains;
  REQUIRE(visible_area_by_silhouettes(panel, view, horizon, sp.p, steps, by_trapezoids, nullptr,
                                      SilhouettePieces::kTrapezoids) == SilhouetteVisibility::kPieces);
  REQUIRE(visible_area_by_silhouettes(panel, view, horizon, sp.p, steps, by_chains, nullptr, SilhouettePieces::kChains) ==
          SilhouetteVisibility::kPieces);
  double area_a = 0, area_b = 0;
  for (std::size_t i = 0; i < by_trapezoids.pieces.size(); ++i) area_a += signed_twice_area(piece_uv(by_trapezoids.pieces, i, view));
  for (std::size_t i = 0; i < by_chains.pieces.size(); ++i) area_b += signed_twice_area(piece_uv(by_chains.pieces, i, view));
  // Hidden: the two triangles' projections, 4 x (0.03 + 0.08) (the light's plane is twice as far).
  CHECK(area_a == doctest::Approx(2 * (panel.area - 0.44)).epsilon(1e-12));
  CHECK(std::abs(area_a - area_b) <= 1e-12 * area_a);
}

TEST_CASE("silhouettes: the answer does not depend on how a surface is triangulated") {
  // One plate as 2 triangles (either diagonal) and as a fan with a T-junction on an edge: every
  // triangulation hides the same part of the light.
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(0.8, 2)));
  const std::vector<std::vector<Tri>> ways = plate_triangulations();
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  ShadeOptions o = options_with(SpecularMethod::kExact);
  for (int k = 0; k < 40; ++k) {
    const ShadingPoint<double> sp = make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0);
    const double open = shade(panel, sp, o).diffuse;
    const double first = shade_shadowed(panel, sp, o, make_bvh(ways[0])).diffuse;
    for (const auto& tris : ways) CHECK(std::abs(shade_shadowed(panel, sp, o, make_bvh(tris)).diffuse - first) <= 1e-12 * open);
  }
}

TEST_CASE("silhouettes: a plate that crosses the light's plane hides the half of the light behind it") {
  // The plate z = 2 + x/2, a 24 x 24 grid of quads over [-3, 3]^2, meets the light's plane
  // (z = 2) along x = 0: from every P under it, the rays to the light's half x < 0 cross it, those
  // to x > 0 pass beyond the light first. Inside the pyramids its only silhouette is the chord
  // along the light's plane; its subtrees face P uniformly, so a search that skipped them without
  // checking that they lie inside the slab would lose that chord and see the light whole.
  std::vector<Tri> plate;
  const int n = 24;
  const double step = 6.0 / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -3 + step * i, y = -3 + step * j;
      add_quad(plate, Vec3d{x, y, 2 + 0.5 * x}, Vec3d{0, step, 0}, Vec3d{step, 0, 0.5 * step});
    }
  const OccluderBvh bvh = make_bvh(plate);
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(0.5, 2)));
  const PreparedLight<double> half =
      prepare_light<double>(area_source({{0, -0.5, 2}, {0, 0.5, 2}, {0.5, 0.5, 2}, {0.5, -0.5, 2}}));
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (const bool clusters : {false, true}) {
    ShadeOptions o = options_with(SpecularMethod::kNone);
    o.shadow_clusters = clusters;
    std::vector<ShadingPoint<double>> points;
    for (int k = 0; k < 64; ++k)
      points.push_back(make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0));
    std::vector<Vec3d> diffuse(points.size());
    accumulate_light_shadowed(panel, o, points.data(), static_cast<long>(points.size()), diffuse.data(), nullptr, bvh);
    double largest = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const double want = shade(half, points[k], o).diffuse, open = shade(panel, points[k], o).diffuse;
      REQUIRE(want < 0.9 * open);
      largest = std::max(largest, std::abs(diffuse[k].x / panel.radiance.x - want) / open);
    }
    CAPTURE(clusters);
    // The plate's part within kLightPlaneMargin (h + light radius) of the light's plane hides
    // nothing: the chord lies that far below the plane, a strip about 5e-7 wide in x here.
    CHECK(largest <= 2e-6);
  }
}

TEST_CASE("silhouettes = triangle cuts: a lathe with jittered poles on a floor, lighting its own vertices") {
  // A pin-like surface of revolution standing on a floor, as exporters write one: its poles are
  // rings of radius 1e-17, so every pole quad splits into a fan triangle and a needle (two pole
  // copies 1e-18 apart and one ring point). Needles hide nothing and a vertex's own fan is left
  // out, so their neighbours' edges are silhouettes whatever way they face, and the subtree search
  // must not skip them. Receivers: the pin's vertices (poles included) and the floor's.
  const PreparedLight<double> panel = prepare_light<double>(
      area_source({{-0.8, 2.6, -1.0}, {0.8, 2.6, -1.0}, {0.8, 2.6, 0.6}, {-0.8, 2.6, 0.6}}));
  const int rings = 12, segments = 16;
  auto profile = [](double s) { return 0.06 + 0.05 * std::sin(3.3 * s); };  // radius along the height
  std::vector<Tri> tris;
  std::vector<ShadingPoint<double>> points;
  auto ring_point = [&](int i, int j) {
    const double s = double(i) / rings, phi = 2 * M_PI * (j % segments) / segments;
    const double r = i == 0 || i == rings ? 1e-17 : profile(s);
    return Vec3d{r * std::cos(phi), 0.38 * s, r * std::sin(phi)};
  };
  for (int j = 0; j < segments; ++j)
    for (int i = 0; i < rings; ++i) {
      const Vec3d a = ring_point(i, j), b = ring_point(i + 1, j), c = ring_point(i + 1, j + 1), d = ring_point(i, j + 1);
      tris.push_back({a, c, b});
      tris.push_back({a, d, c});
    }
  const int n = 16;
  auto floor_point = [&](int i, int k) { return Vec3d{-0.4 + 0.8 * i / n, 0, -0.4 + 0.8 * k / n}; };
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      tris.push_back({floor_point(i, k), floor_point(i, k + 1), floor_point(i + 1, k + 1)});
      tris.push_back({floor_point(i, k), floor_point(i + 1, k + 1), floor_point(i + 1, k)});
    }
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= n; ++k)
      points.push_back(make_shading_point(floor_point(i, k), Vec3d{0, 1, 0}, Vec3d{0, 1, 5}, 10.0));
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const Vec3d p = ring_point(i, j);
      const Vec3d normal = i == rings ? Vec3d{0, 1, 0} : normalize(Vec3d{p.x, 0.02, p.z} + Vec3d{0, i == 0 ? -1.0 : 0.0, 0});
      points.push_back(make_shading_point(p, normal, Vec3d{0, 1, 5}, 10.0));
    }
  const OccluderBvh bvh = make_bvh(tris);
  Agreement agree;
  for (const auto& sp : points) compare(panel, sp, bvh, SpecularMethod::kExact, agree);
  MESSAGE("lathe on a floor: " << agree.shadowed << " of " << agree.cases << " shadowed; diffuse " << agree.diffuse
                               << ", specular " << agree.specular);
  CHECK(agree.shadowed > 30);
  CHECK(agree.diffuse <= 1e-9);
  CHECK(agree.specular <= 1e-7);
}

TEST_CASE("silhouettes = triangle cuts on the paper's bowling lane (assets/paper)") {
  // A real scene: pins whose poles are rings of copies 1e-18 apart (needle triangles), pins
  // standing on the floor (occluders at the receivers' level), 57264 triangles. Every 5th vertex
  // under each of the three panels.
  const LoadedScene loaded = load_scene(std::string(VLIT_SOURCE_DIR) + "/assets/paper/bowling.glb",
                                        std::string(VLIT_SOURCE_DIR) + "/assets/paper/bowling-area.json", {SceneLimits{}, false});
  const Scene& scene = loaded.scene;
  REQUIRE(scene.lights.size() == 3);
  const OccluderBvh bvh(occluders_of(scene));
  Agreement agree;
  for (const LightSource& source : scene.lights) {
    const PreparedLight<double> light = prepare_light<double>(source);
    for (const ScenePrimitive& prim : scene.primitives)
      for (std::size_t v = 0; v < prim.positions.size(); v += 5)
        compare(light, make_shading_point(prim.positions[v], prim.normals[v], Vec3d{0, 1, 5}, 10.0), bvh,
                SpecularMethod::kNone, agree);
  }
  MESSAGE("bowling lane: " << agree.shadowed << " of " << agree.cases << " shadowed; diffuse " << agree.diffuse);
  // The silhouettes decide (without the triangle cuts) at every vertex but the two copies of one
  // pin-top vertex on a seam, under one panel (a slab's count goes below 0 there). The vertices on
  // the pins' seams, whose copies lie 1e-17 apart (the next test), went to the triangle cuts.
  AreaSilhouetteScratch scratch;
  for (const LightSource& source : scene.lights) {
    const PreparedLight<double> light = prepare_light<double>(source);
    for (const ScenePrimitive& prim : scene.primitives) {
      const std::vector<ShadingPoint<double>> points = vertex_points(prim, Vec3d{0, 1, 5}, 10.0);
      ask_silhouettes(area_of(light), points, bvh, scratch);
    }
  }
  MESSAGE("bowling lane: " << scratch.undecided << " of " << scratch.queries << " silhouette queries undecided");
  CHECK(scratch.queries > 60000);
  CHECK(scratch.undecided <= 2);
  CHECK(agree.cases > 15000);
  CHECK(agree.shadowed > 3000);
  CHECK(agree.diffuse <= 1e-8);
}

TEST_CASE("silhouettes: a triangle whose corner lies a rounding error off P leaves the shadow rays decided") {
  // Exporters write a seam's copies of a vertex with coordinates 1e-17 apart (a pin's meridian at
  // z = r sin(pi)): the other copy's triangles then pass through P without touching it exactly,
  // and every shadow ray from P meets one of them at P itself, outside the slab (kApexMargin h
  // from P). Such a hit is not counted and not ambiguous: the silhouette path decides, and agrees
  // with the triangle cuts (which clip the triangle to the slab). The bowling lane had 68 such
  // vertex x light pairs (the previous test).
  const Vec3d p{0.1, 0.05, -1e-17};
  const Vec3d corner{0.1, 0.05, 0};
  // Rising from P (not toward the light: it hides nothing), so that every ray from P crosses its
  // plane just after P.
  std::vector<Tri> tris{{corner, corner + Vec3d{0.1, 0, 0.05}, corner + Vec3d{0, 0.1, 0.05}}};
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(0.5, 2)));
  const ShadingPoint<double> sp = make_shading_point(p, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0);
  for (const bool plate : {false, true}) {
    // With a plate at half the light's height hiding the light beyond x = -0.1 from P, the sweep
    // runs, and its reference ray must be decided too.
    if (plate) add_quad(tris, Vec3d{0, -1, 1}, Vec3d{0, 2, 0}, Vec3d{1, 0, 0});
    const OccluderBvh bvh = make_bvh(tris);
    CAPTURE(plate);
    CHECK(decided_fraction(area_of(panel), {sp}, bvh) == 1.0);
    Agreement agree;
    compare(panel, sp, bvh, SpecularMethod::kExact, agree);
    CHECK(agree.diffuse <= 1e-12);
    CHECK(agree.specular <= 1e-9);
    CHECK(agree.shadowed == (plate ? 1 : 0));
  }
}
