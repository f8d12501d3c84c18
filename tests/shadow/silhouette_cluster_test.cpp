// One BVH search per cluster of vertices (src/shadow/silhouette_cluster.h) against one search per
// vertex: the vertex loop (accumulate_light_shadowed, which clusters area and disk lights) must
// give what shade_shadowed gives at each point alone, on scenes where the cluster's
// classification is stressed: a lane whose pins shadow the floor and each other, a surface
// shadowing its own vertices under a two-sided panel that some clusters straddle, a closed sphere
// lighting and shadowing its own vertices and a floor (back faces culled from some points of a
// cluster and not from others), random soups over a dense floor, and a disk light. The per-vertex
// answers are held to the triangle cuts by silhouette_test.cpp; here a sample is compared with
// the cuts as well. Each case checks that clusters were used, so the test cannot pass on the
// per-vertex fallback alone.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "load/load_scene.h"
#include "shadow/silhouette_cluster.h"
#include "shadow/shadowed_vertices.h"
#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

struct ClusterAgreement {
  double diffuse = 0, specular = 0;  // largest |clustered - per vertex| / unshadowed value
  double cuts = 0;                   // largest |clustered - triangle cuts| / unshadowed, on the sample
  int shadowed = 0, cases = 0;
  double clustered = 0;  // fraction of 16-point groups (in the order given) the lists served
};

// Consecutive groups of 16 points, prepared as the vertex loop prepares its clusters: the
// fraction whose lists (or an empty search) serve the points, not the per-vertex search.
double clustered_fraction(const PreparedAreaLight<double>& polygon, const std::vector<ShadingPoint<double>>& points,
                          const OccluderBvh& bvh) {
  SilhouetteCluster cluster;
  std::vector<std::uint32_t> index(points.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<std::uint32_t>(i);
  int groups = 0, served = 0;
  for (std::size_t begin = 0; begin < points.size(); begin += 16) {
    const int n = static_cast<int>(std::min<std::size_t>(16, points.size() - begin));
    bool lit = false;
    for (int i = 0; i < n && !lit; ++i) lit = make_area_view(polygon, points[begin + i].p).lit;
    if (!lit) continue;
    prepare_silhouette_cluster(polygon, points.data(), index.data() + begin, n, bvh, cluster);
    ++groups;
    served += cluster.state != SilhouetteCluster::State::kPerVertex;
  }
  return groups ? static_cast<double>(served) / groups : 0.0;
}

ClusterAgreement compare_clusters(const PreparedLight<double>& light, const std::vector<ShadingPoint<double>>& points,
                                  const OccluderBvh& bvh, SpecularMethod method, int cut_stride) {
  const ShadeOptions options = options_with(method);
  ShadeOptions cuts = options;
  cuts.area_shadows = AreaShadowMethod::kTriangleCuts;
  const long n = static_cast<long>(points.size());
  std::vector<Vec3d> diffuse(n), specular(n);
  accumulate_light_shadowed(light, options, points.data(), n, diffuse.data(), specular.data(), bvh);
  ClusterAgreement out;
  for (long i = 0; i < n; ++i) {
    const Response<double> alone = shade_shadowed(light, points[i], options, bvh);
    const Response<double> open = shade(light, points[i], options);
    const double d = diffuse[i].x / light.radiance.x, s = specular[i].x / light.radiance.x;
    REQUIRE(std::isfinite(d));
    REQUIRE(std::isfinite(s));
    CHECK(d >= 0);
    if (open.diffuse > 0) out.diffuse = std::max(out.diffuse, std::abs(d - alone.diffuse) / open.diffuse);
    if (open.specular > 0) out.specular = std::max(out.specular, std::abs(s - alone.specular) / open.specular);
    out.shadowed += alone.diffuse < open.diffuse * (1 - 1e-9);
    ++out.cases;
    if (cut_stride > 0 && i % cut_stride == 0 && open.diffuse > 0)
      out.cuts = std::max(out.cuts, std::abs(d - shade_shadowed(light, points[i], cuts, bvh).diffuse) / open.diffuse);
  }
  std::visit(
      [&](const auto& k) {
        using K = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<K, PreparedAreaLight<double>> || std::is_same_v<K, PreparedDiskLight<double>>)
          out.clustered = clustered_fraction(shadowed_polygon(k), points, bvh);
      },
      light.kernel);
  return out;
}

void report(const char* name, const ClusterAgreement& a) {
  MESSAGE(std::string(name) << ": " << a.shadowed << " of " << a.cases << " shadowed; clustered - alone: diffuse " << a.diffuse
               << ", specular " << a.specular << "; clustered - cuts " << a.cuts << "; groups served by clusters "
               << a.clustered);
}

}  // namespace

TEST_CASE("clusters = one search per vertex: the paper's bowling lane, every vertex under its 3 panels") {
  const LoadedScene loaded = load_scene(std::string(VLIT_SOURCE_DIR) + "/assets/paper/bowling.glb",
                                        std::string(VLIT_SOURCE_DIR) + "/assets/paper/bowling-area.json", {SceneLimits{}, false});
  const Scene& scene = loaded.scene;
  REQUIRE(scene.lights.size() == 3);
  const OccluderBvh bvh(occluders_of(scene));
  ClusterAgreement all;
  double served = 0;
  int lights = 0;
  for (const LightSource& source : scene.lights) {
    const PreparedLight<double> light = prepare_light<double>(source);
    for (const ScenePrimitive& prim : scene.primitives) {
      const std::vector<ShadingPoint<double>> points = vertex_points(prim, Vec3d{0, 1, 5}, 10.0);
      const ClusterAgreement a = compare_clusters(light, points, bvh, SpecularMethod::kNone, 97);
      all.diffuse = std::max(all.diffuse, a.diffuse);
      all.cuts = std::max(all.cuts, a.cuts);
      all.shadowed += a.shadowed;
      all.cases += a.cases;
    }
    std::vector<ShadingPoint<double>> lane;
    const ScenePrimitive& floor = scene.primitives[0];
    for (std::size_t v = 0; v < floor.positions.size(); ++v)
      lane.push_back(make_shading_point(floor.positions[v], floor.normals[v], Vec3d{0, 1, 5}, 10.0));
    served += clustered_fraction(std::get<PreparedAreaLight<double>>(light.kernel), lane, bvh);
    ++lights;
  }
  all.clustered = served / lights;
  report("bowling lane", all);
  CHECK(all.cases > 90000);
  CHECK(all.shadowed > 15000);
  CHECK(all.diffuse <= 1e-12);
  CHECK(all.cuts <= 1e-8);
  CHECK(all.clustered >= 0.8);
}

TEST_CASE("clusters = one search per vertex: a surface shadowing its own vertices, a two-sided panel across it") {
  // Vertices on both sides of the panel's plane: clusters that straddle it search per vertex, the
  // others use their lists; occluders next to P cross its slab (chords), facings vary within
  // clusters.
  const PreparedLight<double> panel =
      prepare_light<double>(area_source({{0.1, -0.7, 0.9}, {0.1, 0.7, 0.9}, {-0.2, 0.7, 1.6}, {-0.2, -0.7, 1.6}}, true));
  const BumpySurface surface = bumpy_surface(40, 0.35);
  const OccluderBvh bvh = make_bvh(surface.tris);
  const std::vector<ShadingPoint<double>>& points = surface.points;
  const ClusterAgreement a = compare_clusters(panel, points, bvh, SpecularMethod::kExact, 7);
  report("bumpy surface", a);
  CHECK(a.shadowed > 100);
  CHECK(a.diffuse <= 1e-12);
  CHECK(a.specular <= 1e-10);
  CHECK(a.cuts <= 1e-9);
  // Groups of 16 in row order cross the panel's plane in most rows (and at the rows' ends):
  // those search per vertex.
  CHECK(a.clustered >= 0.2);
  CHECK(a.clustered < 0.9);
}

// A closed sphere and a closed table over a floor under a panel, every coordinate x mapped to
// x * scale + offset; the floor points and the sphere's own corners as receivers.
ClusterAgreement sphere_and_table_over_floor(double scale, const Vec3d& offset) {
  // Closed solids cull their back faces from points outside their box. The sphere: floor clusters
  // lie outside its box, clusters of its own vertices inside it. A second solid, a slab on a
  // pillar standing on the floor, holds floor points under the slab in its box: from there its
  // back faces count (silhouette edges of weight 2), from farther floor points they are culled.
  auto at = [&](const Vec3d& x) { return x * scale + offset; };
  std::vector<Tri> sphere = icosphere({0.1, -0.05, 1.2}, 0.5, 3);
  std::vector<Tri> table;
  add_box(table, {-1.4, 0.3, 0.6}, {-0.2, 1.2, 0.75});
  add_box(table, {-1.4, 1.25, 0}, {-1.25, 1.4, 0.75});
  std::vector<Tri> floor;
  add_quad(floor, {-3, -3, 0}, {6, 0, 0}, {0, 6, 0});
  for (std::vector<Tri>* mesh : std::initializer_list<std::vector<Tri>*>{&sphere, &table, &floor})
    for (Tri& t : *mesh)
      for (Vec3d& x : t) x = at(x);
  OccluderTriangles occluders;
  for (const std::vector<Tri>* solid : {&sphere, &table}) {
    Aabb box;
    for (const Tri& t : *solid) {
      occluders.corners.push_back(t);
      occluders.ids.push_back({static_cast<std::uint32_t>(occluders.solid_bounds.size()), 0});
      occluders.solid.push_back(static_cast<int>(occluders.solid_bounds.size()));
      for (const Vec3d& x : t) box.grow(x);
    }
    occluders.solid_bounds.push_back(box);
  }
  for (std::size_t i = 0; i < floor.size(); ++i) {
    occluders.corners.push_back(floor[i]);
    occluders.ids.push_back({1, static_cast<std::uint32_t>(i)});
    occluders.solid.push_back(-1);
  }
  const OccluderBvh bvh(std::move(occluders));
  const PreparedLight<double> panel = prepare_light<double>(
      area_source({at({-0.4, -1.4, 2.6}), at({-0.4, 0.6, 2.6}), at({1.6, 0.6, 2.2}), at({1.6, -1.4, 2.2})}));
  std::vector<ShadingPoint<double>> points;
  const int n = 48;
  const Vec3d eye = at({0.5, 0, 4});
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      points.push_back(make_shading_point(at(Vec3d{-1.5 + 3.0 * i / n, -1.5 + 3.0 * j / n, 0}), Vec3d{0, 0, 1}, eye, 12.0));
  for (const Tri& t : sphere) {  // its own corners, with the face normal (every corner is a vertex of 5-6 faces)
    const Vec3d nrm = normalize(cross(t[1] - t[0], t[2] - t[0]));
    points.push_back(make_shading_point(t[0], nrm, eye, 12.0));
  }
  return compare_clusters(panel, points, bvh, SpecularMethod::kExact, 5);
}

TEST_CASE("clusters = one search per vertex: a closed sphere over a floor, lighting its own vertices") {
  const ClusterAgreement a = sphere_and_table_over_floor(1, {});
  report("sphere over a floor", a);
  CHECK(a.shadowed > 200);
  CHECK(a.diffuse <= 1e-12);
  CHECK(a.specular <= 1e-10);
  CHECK(a.cuts <= 1e-9);
  CHECK(a.clustered >= 0.9);
}

TEST_CASE("clusters = one search per vertex: the sphere and table scene tiny, huge and far from the origin") {
  // The classification's margins are relative: the same scene at 1e-4 and 1e4 of its size, and
  // 1e5 away from the origin, gives the same agreement (and is as often clustered).
  const struct {
    const char* name;
    double scale;
    Vec3d offset;
  } cases[] = {{"scaled by 1e-4", 1e-4, {}}, {"scaled by 1e4", 1e4, {}}, {"moved by (1e5, -1e5, 1e3)", 1, {1e5, -1e5, 1e3}}};
  for (const auto& c : cases) {
    const ClusterAgreement a = sphere_and_table_over_floor(c.scale, c.offset);
    report(c.name, a);
    CHECK(a.shadowed > 200);
    CHECK(a.diffuse <= 1e-12);
    CHECK(a.specular <= 1e-10);
    CHECK(a.cuts <= 1e-9);
    CHECK(a.clustered >= 0.9);
  }
}

TEST_CASE("clusters = one search per vertex: random soups over a dense floor, a panel and a disk") {
  std::mt19937_64 rng(2611);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  const PreparedLight<double> lights[2] = {
      prepare_light<double>(area_source(square_light(0.7, 2))),
      prepare_light<double>(disk_source({0.2, -0.1, 2.2}, normalize(Vec3d{0.2, 0.1, -1}), 0.8))};
  ClusterAgreement all[2];
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<Tri> tris;
    add_random_triangles(tris, rng, 20 + static_cast<int>(rng() % 60));
    const OccluderBvh bvh = make_bvh(tris);
    std::vector<ShadingPoint<double>> points;
    const int n = 32;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        points.push_back(make_shading_point(Vec3d{-1.5 + 3.0 * i / n, -1.5 + 3.0 * j / n, 0}, Vec3d{0, 0, 1},
                                            Vec3d{0.3, -0.2, 3}, 20.0));
    for (int l = 0; l < 2; ++l) {
      INFO("trial " << trial << ", light " << l);
      const ClusterAgreement a = compare_clusters(lights[l], points, bvh, SpecularMethod::kExact, 11);
      all[l].diffuse = std::max(all[l].diffuse, a.diffuse);
      all[l].specular = std::max(all[l].specular, a.specular);
      all[l].cuts = std::max(all[l].cuts, a.cuts);
      all[l].shadowed += a.shadowed;
      all[l].cases += a.cases;
      all[l].clustered += a.clustered / 6;
    }
  }
  report("soups, panel", all[0]);
  report("soups, disk", all[1]);
  for (const ClusterAgreement& a : all) {
    CHECK(a.shadowed > a.cases / 4);
    CHECK(a.diffuse <= 1e-12);
    CHECK(a.specular <= 1e-10);
    CHECK(a.clustered >= 0.5);  // groups of 16 in row order: the wider ones than the light search alone
  }
  // The disk's pieces (of its circumscribed 64-gon, intersected with the disk) from silhouettes and
  // from triangle cuts: 8.6e-15 apart here. Trapezoids with a degenerate side broke the disk's
  // clipping by 1.35 of the open value before short edges were skipped (disk_pieces.cpp).
  CHECK(all[0].cuts <= 1e-9);
  CHECK(all[1].cuts <= 1e-9);
}

namespace {

// As the Khronos MetalRoughSpheres sample: a 4 x 4 grid of spheres 0.7 apart from their
// neighbours' surfaces, every vertex a receiver.
void sphere_grid(std::vector<Tri>& tris, std::vector<ShadingPoint<double>>& points) {
  const std::vector<Tri> unit = icosphere({0, 0, 0}, 0.35, 2);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const Vec3d center{1.0 * i, 1.0 * j, 0};
      for (const Tri& t : unit) {
        tris.push_back({t[0] + center, t[1] + center, t[2] + center});
        points.push_back(make_shading_point(t[0] + center, normalize(t[0]), Vec3d{1.5, 1.5, 6}, 10.0));
      }
    }
}

}  // namespace

TEST_CASE("clusters = one search per vertex: a grid of spheres lighting each other's vertices under small panels") {
  // Panels of the spheres' spacing not far above. A cluster's search leaves out triangles that a
  // vertex's own (looser, corner-by-plane) test keeps: those must be weighed per vertex, not from
  // the cluster's stale classification.
  std::vector<Tri> tris;
  std::vector<ShadingPoint<double>> points;
  sphere_grid(tris, points);
  const OccluderBvh bvh = make_bvh(tris);
  ClusterAgreement all;
  for (const Vec3d& c : {Vec3d{-0.2, -0.2, 1.2}, Vec3d{3.2, 0.3, 0.9}, Vec3d{1.5, 3.2, 0.8}, Vec3d{1.5, 1.5, 3}}) {
    const PreparedLight<double> panel = prepare_light<double>(
        area_source({c + Vec3d{-1, -1, 0}, c + Vec3d{-1, 1, 0}, c + Vec3d{1, 1, 0}, c + Vec3d{1, -1, 0}}));
    const ClusterAgreement a = compare_clusters(panel, points, bvh, SpecularMethod::kNone, 0);
    all.diffuse = std::max(all.diffuse, a.diffuse);
    all.shadowed += a.shadowed;
    all.cases += a.cases;
    all.clustered = std::max(all.clustered, a.clustered);
  }
  report("grid of spheres", all);
  CHECK(all.shadowed > all.cases / 8);
  CHECK(all.diffuse <= 1e-12);
  CHECK(all.clustered >= 0.5);
}

TEST_CASE("clusters: their size does not change the result") {
  // A vertex reads an edge only through the first of the cluster's leaves that lists it, and the
  // facings of the cluster's variable triangles from their stored planes; clusters of 1 to 200
  // vertices must light every vertex as the default size does, shadowed or not.
  std::vector<Tri> tris;
  std::vector<ShadingPoint<double>> points;
  sphere_grid(tris, points);
  const OccluderBvh bvh = make_bvh(tris);
  const long n = static_cast<long>(points.size());
  ShadeOptions options = options_with(SpecularMethod::kExact);
  for (const Vec3d& c : {Vec3d{-0.2, -0.2, 1.2}, Vec3d{3.2, 0.3, 0.9}}) {
    const PreparedLight<double> panel = prepare_light<double>(
        area_source({c + Vec3d{-1, -1, 0}, c + Vec3d{-1, 1, 0}, c + Vec3d{1, 1, 0}, c + Vec3d{1, -1, 0}}));
    options.shadow_cluster_size = ShadeOptions{}.shadow_cluster_size;
    std::vector<Vec3d> diffuse(n), specular(n);
    accumulate_light_shadowed(panel, options, points.data(), n, diffuse.data(), specular.data(), bvh);
    int shadowed = 0;
    for (long i = 0; i < n; ++i)
      shadowed += diffuse[i].x < shade(panel, points[i], options).diffuse * panel.radiance.x * (1 - 1e-9);
    MESSAGE("panel at " << c.x << ", " << c.y << ", " << c.z << ": " << shadowed << " of " << n << " vertices shadowed");
    CHECK(shadowed > n / 8);
    for (int size : {1, 3, 16, 200}) {
      CAPTURE(size);
      options.shadow_cluster_size = size;
      std::vector<Vec3d> d(n), s(n);
      accumulate_light_shadowed(panel, options, points.data(), n, d.data(), s.data(), bvh);
      double largest = 0;
      for (long i = 0; i < n; ++i)
        largest = std::max({largest, std::abs(d[i].x - diffuse[i].x) / std::max(diffuse[i].x, 1e-300),
                            std::abs(s[i].x - specular[i].x) / std::max(specular[i].x, 1e-300)});
      CHECK(largest <= 1e-13);
    }
  }
}

TEST_CASE("clusters = one search per vertex: a closed box wider than the light's pyramid hides a floor") {
  // Every triangle of the box that the pyramids reach faces the points uniformly and its
  // silhouette lies outside the pyramids: the searches return no candidate at all, and only the
  // shadow ray finds that the light is hidden. A cluster with no candidate is not a lit one.
  // The box's faces cut into 32 x 32 quads, so that BVH leaves hold triangles of one face.
  std::vector<Tri> box, tris;
  add_box(box, {-3, -3, 0.5}, {3, 3, 1.75});
  const int cuts = 32;
  for (std::size_t f = 0; f < box.size(); f += 2) {  // add_box writes each face as two triangles of one quad
    const Vec3d corner = box[f][0], e1 = box[f][1] - box[f][0], e2 = box[f + 1][2] - box[f][0];
    for (int i = 0; i < cuts; ++i)
      for (int j = 0; j < cuts; ++j)
        add_quad(tris, corner + e1 * (double(i) / cuts) + e2 * (double(j) / cuts), e1 / cuts, e2 / cuts);
  }
  const OccluderBvh bvh = make_bvh(tris);
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(0.5, 2)));
  std::vector<ShadingPoint<double>> points;
  for (int j = 0; j <= 16; ++j)
    for (int i = 0; i <= 16; ++i)
      points.push_back(make_shading_point(Vec3d{-0.8 + 0.1 * i, -0.8 + 0.1 * j, 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0));
  const ClusterAgreement a = compare_clusters(panel, points, bvh, SpecularMethod::kExact, 3);
  report("box wider than the pyramids", a);
  CHECK(a.shadowed == a.cases);
  CHECK(a.diffuse <= 1e-12);
  CHECK(a.specular <= 1e-12);
  CHECK(a.cuts <= 1e-12);
  CHECK(a.clustered == 1);
}

TEST_CASE("clusters: one too wide for a finely tessellated sphere is not prepared, and the answers do not change") {
  // shadow_bench part 3b's scene: a sphere of radius 0.3 between a unit square panel and a floor.
  // From a 4 x 4 block of floor points, the band of triangles whose facing varies over the block
  // grows with the number of triangles, a point's own silhouette only with its square root: the
  // coarse sphere's clusters are prepared, the fine sphere's are not (their points search alone).
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(0.5, 2)));
  const PreparedAreaLight<double>& polygon = std::get<PreparedAreaLight<double>>(panel.kernel);
  std::vector<ShadingPoint<double>> points;  // 16 blocks of 4 x 4 points, one block after another
  for (int block = 0; block < 16; ++block)
    for (int k = 0; k < 16; ++k) {
      const int i = 4 * (block % 4) + k % 4, j = 4 * (block / 4) + k / 4;
      points.push_back(make_shading_point(Vec3d{-1 + (i + 0.5) / 8, -1 + (j + 0.5) / 8, 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 5}, 10.0));
    }
  double served[2];
  for (int fine = 0; fine < 2; ++fine) {
    CAPTURE(fine);
    const OccluderBvh bvh = make_bvh(icosphere({0, 0, 1}, 0.3, fine ? 6 : 2));
    ClusterAgreement a = compare_clusters(panel, points, bvh, SpecularMethod::kNone, fine ? 0 : 5);
    served[fine] = a.clustered = clustered_fraction(polygon, points, bvh);
    report(fine ? "fine sphere" : "coarse sphere", a);
    CHECK(a.shadowed > a.cases / 4);
    CHECK(a.diffuse <= 1e-12);
    CHECK(a.cuts <= 1e-12);
  }
  CHECK(served[0] == 1);
  CHECK(served[1] <= 0.5);
}

TEST_CASE("clusters: vertices at one position whose horizons clip the light alike share one search") {
  // Every vertex of a surface shadowing itself, split into 4 vertices at its position (as at a
  // seam): its normal twice, and tilted by 0.2 and -0.6 rad about y. Under the steep panel beside
  // the surface and the disk above it, some copies keep the whole light above their horizon
  // (they share one search), the two with the same normal share one whatever their horizon
  // keeps, and the tilted ones that cut the light differently search alone. The vertex loop must
  // give each vertex what its own search gives.
  const BumpySurface surface = bumpy_surface(24, 0.35);
  const OccluderBvh bvh = make_bvh(surface.tris);
  const PreparedLight<double> lights[2] = {
      prepare_light<double>(area_source({{2.4, -0.6, 0.3}, {2.4, 0.6, 0.3}, {2.7, 0.6, 1.2}, {2.7, -0.6, 1.2}}, true)),
      prepare_light<double>(disk_source({0.9, 0.2, 1.4}, normalize(Vec3d{-0.5, 0, -1}), 0.5))};
  constexpr int kCopies = 4;
  std::vector<ShadingPoint<double>> points;
  for (const ShadingPoint<double>& sp : surface.points)
    for (const double tilt : {0.0, 0.0, 0.2, -0.6}) {
      const Vec3d n{sp.n.x * std::cos(tilt) + sp.n.z * std::sin(tilt), sp.n.y, -sp.n.x * std::sin(tilt) + sp.n.z * std::cos(tilt)};
      points.push_back(make_shading_point(sp.p, n, Vec3d{0, 0, 5}, 10.0));
    }
  for (int l = 0; l < 2; ++l) {
    const PreparedAreaLight<double>& polygon =
        l == 0 ? std::get<PreparedAreaLight<double>>(lights[l].kernel)
               : shadowed_polygon(std::get<PreparedDiskLight<double>>(lights[l].kernel));
    // How many positions have two or more copies that keep the whole polygon above their horizon
    // (or the same normal and a cut one) and are partly shadowed: the shared searches answer them.
    int whole_shared = 0, cut_shared = 0;
    for (std::size_t first = 0; first < points.size(); first += kCopies) {
      int whole = 0;
      bool shadowed = false;
      for (std::size_t k = first; k < first + kCopies; ++k) {
        const AreaView<double> view = make_area_view(polygon, points[k].p);
        ClipPolygon<double> horizon;
        clip_to_horizon(polygon, view, points[k].n, horizon);
        const bool kept_whole = horizon.count == polygon.count &&
                                std::equal(horizon.d.begin(), horizon.d.begin() + horizon.count, polygon.d.begin());
        whole += kept_whole;
        const double open = shade(lights[l], points[k], options_with(SpecularMethod::kNone)).diffuse;
        const double seen = shade_shadowed(lights[l], points[k], options_with(SpecularMethod::kNone), bvh).diffuse;
        shadowed = shadowed || (seen > 0 && seen < open * (1 - 1e-6));
        if (k == first && view.lit && horizon.count >= 3 && !kept_whole) cut_shared += seen > 0 && seen < open * (1 - 1e-6);
      }
      whole_shared += whole >= 2 && shadowed;
    }
    const ClusterAgreement a = compare_clusters(lights[l], points, bvh, SpecularMethod::kExact, 5);
    report(l == 0 ? "split vertices, panel" : "split vertices, disk", a);
    MESSAGE("positions sharing: whole light " << whole_shared << ", same normal and a cut light " << cut_shared);
    CHECK(whole_shared + cut_shared > 50);
    CHECK(a.diffuse <= 1e-12);
    CHECK(a.specular <= 1e-10);
    CHECK(a.cuts <= 1e-9);
  }
}
