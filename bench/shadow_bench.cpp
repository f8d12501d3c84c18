// Shadow benchmark (docs/shadows.md): what soft shadows cost, and how the cost grows.
//
//   shadow_bench [--quick] [--only 1|2|3] [--scene bowling.glb --lights bowling-area.json]
//                [--no-cuts] [--cluster-sizes 16,64] [--repeat N]
//
// 1. The bowling scene with its area lights: the whole vertex loop with shadows off, on from
//    silhouettes (the default) and on from triangle cuts (the previous method, the tests'
//    reference), all cores, same process; ratio to off and the largest difference between the
//    two shadowed results (relative to the largest value). --cluster-sizes adds a row per size of
//    the clusters of vertices (the default is ShadeOptions::shadow_cluster_size).
// 2. Against the dense shadow-ray estimate at equal error: on vertices of that scene whose light
//    is partly hidden, the stratified shadow-ray estimate of the diffuse (rays through our BVH)
//    with N = 8 .. 8192 samples per light: RMS of (estimate - our exact value) / unshadowed value
//    (relative to the light the vertex would get unhidden: penumbra vertices near the horizon
//    have tiny values) and time per vertex, next to ours. (Ours agrees with an independent brute-force reference
//    within its sampling error: tests/shadow/.)
// 3. Cost per vertex as the occluder triangles grow from 1e2 to 1e6, one thread:
//    (a) the scene grows: a field of small triangles at constant density around a fixed light
//        and receiver (the triangles that matter stay about the same);
//    (b) the occluder is refined: one sphere between the light and the receiver, tessellated
//        ever finer (every triangle of its near half matters); up to 1e6 triangles.
//    Silhouettes against triangle cuts (time ratio, largest difference relative to the mean),
//    the cuts up to 1e4 triangles for the sphere (their cost grows faster than the triangles).
//    Beside them, a tube light across the square's middle over the same occluders: its visible
//    intervals from silhouettes (linear_silhouette.h, the default) against every triangle's
//    interval (linear_visibility.h, the reference), time ratio and largest difference.
//    --repeat N: each silhouette loop of part 3 runs N times and the fastest run is reported (a
//    busy machine only adds time; the results are the same bits every time).
//    --min-triangles N: only the rows of at least about N triangles (to profile the large ones,
//    e.g. `perf record shadow_bench --only 3 --no-cuts --min-triangles 1000000 --repeat 12`).
// --quick: small sizes only (a few seconds; ctest shadow_bench_quick checks that it runs).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <omp.h>

#include "bake/light_vertices.h"
#include "shadow/shadowed_vertices.h"
#include "load/load_scene.h"
#include "scene/material.h"
#include "shadow/occluder_bvh.h"
#include "shadow/shadowed_light.h"

namespace vlit::bench {
namespace {

// Times are CPU seconds (the build machine is shared: wall time measures the neighbours): of the
// calling thread for the one-thread measurements, of the process for the multi-threaded loop.
struct Clock {
  using time_point = double;
  static double now() { return cpu_seconds(CLOCK_THREAD_CPUTIME_ID); }
  static double cpu_seconds(clockid_t id) {
    timespec ts{};
    clock_gettime(id, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
  }
};
double seconds_since(double t) { return Clock::now() - t; }
double process_seconds() { return Clock::cpu_seconds(CLOCK_PROCESS_CPUTIME_ID); }

using Tri = std::array<Vec3d, 3>;

OccluderBvh make_bvh(const std::vector<Tri>& tris, bool brute_force = false) {
  OccluderTriangles t;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    t.corners.push_back(tris[i]);
    t.ids.push_back({0, static_cast<std::uint32_t>(i)});
  }
  return OccluderBvh(std::move(t), brute_force);
}

// The same triangles as one closed primitive (corners shared by position).
OccluderBvh closed_bvh(const std::vector<Tri>& tris, bool brute_force = false) {
  Scene scene;
  ScenePrimitive prim;
  for (const Tri& t : tris)
    for (const Vec3d& c : t) {
      prim.triangles.push_back(static_cast<std::uint32_t>(prim.positions.size()));
      prim.positions.push_back(c);
    }
  prim.normals.assign(prim.positions.size(), Vec3d{0, 0, 1});
  scene.primitives.push_back(std::move(prim));
  return OccluderBvh(occluders_of(scene), brute_force);
}

// Stratified (jittered grid) shadow-ray estimate of an area light's diffuse at sp.
double shadow_ray_diffuse(const LightSource& light, const ShadingPoint<double>& sp, const OccluderBvh& bvh, int grid,
                          std::mt19937_64& rng) {
  std::uniform_real_distribution<double> jitter(0, 1);
  const auto& q = light.polygon;
  Vec3d newell{};
  for (std::size_t i = 0; i < q.size(); ++i) newell += cross(q[i], q[(i + 1) % q.size()]);
  const Vec3d nl = normalize(newell);
  double total = 0;
  for (std::size_t k = 1; k + 1 < q.size(); ++k) {  // fan triangles, uniform samples on each
    const Vec3d a = q[0], b = q[k], c = q[k + 1];
    const double area = 0.5 * length(cross(b - a, c - a));
    double sum = 0;
    for (int i = 0; i < grid; ++i)
      for (int j = 0; j < grid; ++j) {
        const double s = std::sqrt((i + jitter(rng)) / grid), t = (j + jitter(rng)) / grid;
        const Vec3d y = a * (1 - s) + b * (s * (1 - t)) + c * (s * t);
        const Vec3d w = y - sp.p;
        const double r2 = length_squared(w);
        const double cos_theta = dot(sp.n, w), cos_l = -dot(nl, w);
        if (cos_theta <= 0 || cos_l <= 0) continue;
        if (bvh.segment_occluded(sp.p, y, sp.p)) continue;
        sum += cos_theta * cos_l / (r2 * r2);
      }
    total += area * sum / (grid * grid);
  }
  return total;
}

void bowling(const std::string& scene_path, const std::string& lights_path, bool quick, bool part1, bool part2,
             bool with_cuts, const std::vector<int>& cluster_sizes) {
  LoadedScene loaded = load_scene(scene_path, lights_path, {SceneLimits{}, false});
  Scene& scene = loaded.scene;
  std::printf("## 1. %s with %s: whole vertex loop (%zu vertices, %zu lights, all cores)\n\n", scene_path.c_str(),
              lights_path.c_str(), scene.vertex_count(), scene.lights.size());
  LightingRequest request;
  request.shade.with_specular = false;
  double t_off = 0, t_on = 0;
  std::vector<VertexLight> off, on;
  if (!quick && part1) {
    // One untimed loop of each kind first: the first shadowed one also pays for first touching the
    // threads' per-triangle tables (page faults), which made the default row, timed first, the
    // slowest in most runs; after them every row is measured alike.
    light_scene_vertices(scene, request);
    request.shadows = true;
    light_scene_vertices(scene, request);
    request.shadows = false;
    auto wall = std::chrono::steady_clock::now();
    auto wall_since = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(); };
    double t = process_seconds();
    off = light_scene_vertices(scene, request);
    t_off = process_seconds() - t;
    const double wall_off = wall_since();
    request.shadows = true;
    t = process_seconds();
    wall = std::chrono::steady_clock::now();
    on = light_scene_vertices(scene, request);
    t_on = process_seconds() - t;
    const double wall_on = wall_since();
    // Other cluster sizes (the default's results, other times).
    struct SizeRow { int size; double wall, cpu, difference; };
    std::vector<SizeRow> size_rows;
    for (int size : cluster_sizes) {
      request.shade.shadow_cluster_size = size;
      t = process_seconds();
      wall = std::chrono::steady_clock::now();
      const std::vector<VertexLight> sized = light_scene_vertices(scene, request);
      SizeRow row{size, wall_since(), process_seconds() - t, 0};
      for (std::size_t p = 0; p < on.size(); ++p)
        for (std::size_t v = 0; v < on[p].diffuse.size(); ++v)
          for (int c = 0; c < 3; ++c)
            row.difference = std::max(row.difference, std::abs(double(on[p].diffuse[v][c]) - sized[p].diffuse[v][c]));
      size_rows.push_back(row);
    }
    request.shade.shadow_cluster_size = ShadeOptions{}.shadow_cluster_size;
    request.shade.shadow_clusters = false;
    t = process_seconds();
    wall = std::chrono::steady_clock::now();
    const std::vector<VertexLight> alone = light_scene_vertices(scene, request);
    const double t_alone = process_seconds() - t;
    const double wall_alone = wall_since();
    request.shade.area_shadows = AreaShadowMethod::kTriangleCuts;
    t = process_seconds();
    wall = std::chrono::steady_clock::now();
    const std::vector<VertexLight> cuts = with_cuts ? light_scene_vertices(scene, request) : alone;
    const double t_cuts = process_seconds() - t;
    const double wall_cuts = wall_since();
    double alone_difference = 0;
    double dark = 0, total = 0, largest = 0, difference = 0;
    for (std::size_t p = 0; p < on.size(); ++p)
      for (std::size_t v = 0; v < on[p].diffuse.size(); ++v) {
        total += 1;
        dark += on[p].diffuse[v].x < off[p].diffuse[v].x * (1 - 1e-6);  // off ran the float batch kernels
        for (int c = 0; c < 3; ++c) {
          largest = std::max(largest, std::abs(double(cuts[p].diffuse[v][c])));
          difference = std::max(difference, std::abs(double(on[p].diffuse[v][c]) - cuts[p].diffuse[v][c]));
          alone_difference = std::max(alone_difference, std::abs(double(on[p].diffuse[v][c]) - alone[p].diffuse[v][c]));
        }
      }
    std::printf("| shadows | wall time (s) | CPU time, all threads (s) | CPU µs per vertex | ratio to off (wall) | ratio to off (CPU) |\n|---|---|---|---|---|---|\n");
    std::printf("| off | %.3f | %.3f | %.2f | 1 | 1 |\n", wall_off, t_off, 1e6 * t_off / total);
    std::printf("| on, silhouettes, clusters of vertices (default) | %.3f | %.3f | %.2f | %.1f | %.1f |\n", wall_on, t_on,
                1e6 * t_on / total, wall_on / wall_off, t_on / t_off);
    for (const SizeRow& row : size_rows)
      std::printf("| on, silhouettes, clusters of %d vertices (largest difference to the default: %.1e) | %.3f | %.3f | "
                  "%.2f | %.1f | %.1f |\n",
                  row.size, row.difference, row.wall, row.cpu, 1e6 * row.cpu / total, row.wall / wall_off, row.cpu / t_off);
    std::printf("| on, silhouettes, one search per vertex | %.3f | %.3f | %.2f | %.1f | %.1f |\n", wall_alone, t_alone,
                1e6 * t_alone / total, wall_alone / wall_off, t_alone / t_off);
    if (with_cuts)
      std::printf("| on, triangle cuts | %.3f | %.3f | %.2f | %.1f | %.1f |\n", wall_cuts, t_cuts, 1e6 * t_cuts / total,
                  wall_cuts / wall_off, t_cuts / t_off);
    std::printf("\n%.0f of %.0f vertices (%.1f%%) lose more than 1e-6 of their light to a shadow. Largest difference, "
                "clusters against one search per vertex: %.2e of the largest value", dark, total, 100 * dark / total,
                alone_difference / largest);
    if (with_cuts) std::printf("; against triangle cuts: %.2e", difference / largest);
    std::printf(".\n\n");
  }

  if (!part2) return;
  // 2. Shadow rays at equal error, on vertices in penumbra.
  OccluderBvh bvh(occluders_of(scene));
  std::vector<PreparedLight<double>> lights;
  for (const LightSource& l : scene.lights) lights.push_back(prepare_light<double>(l));
  std::vector<ShadingPoint<double>> penumbra;
  ShadeOptions diffuse_only;
  diffuse_only.with_specular = false;
  diffuse_only.specular.method = SpecularMethod::kNone;
  std::mt19937_64 pick(17);
  const std::size_t wanted = quick ? 8 : 200;
  for (int attempt = 0; attempt < 200000 && penumbra.size() < wanted; ++attempt) {
    const ScenePrimitive& prim = scene.primitives[pick() % scene.primitives.size()];
    if (prim.positions.empty()) continue;
    const std::size_t v = pick() % prim.positions.size();
    const ShadingPoint<double> sp = make_shading_point(prim.positions[v], prim.normals[v], Vec3d{0, 1, 5}, 10.0);
    const double open = shade(lights[0], sp, diffuse_only).diffuse;
    const double hidden = shade_shadowed(lights[0], sp, diffuse_only, bvh).diffuse;
    if (open > 0 && hidden > 0.05 * open && hidden < 0.95 * open) penumbra.push_back(sp);
  }
  std::printf("## 2. Exact visibility against stratified shadow rays (light '%s', %zu vertices in its penumbra, one thread)\n\n",
              scene.lights[0].name.c_str(), penumbra.size());
  std::vector<double> exact(penumbra.size()), open(penumbra.size());
  for (std::size_t i = 0; i < penumbra.size(); ++i) open[i] = shade(lights[0], penumbra[i], diffuse_only).diffuse;
  auto t = Clock::now();
  for (std::size_t i = 0; i < penumbra.size(); ++i) exact[i] = shade_shadowed(lights[0], penumbra[i], diffuse_only, bvh).diffuse;
  const double t_exact = seconds_since(t) / std::max<std::size_t>(1, penumbra.size());
  ShadeOptions cut_options = diffuse_only;
  cut_options.area_shadows = AreaShadowMethod::kTriangleCuts;
  double cut_error = 0;
  t = Clock::now();
  for (std::size_t i = 0; i < penumbra.size(); ++i)
    cut_error = std::max(cut_error, std::abs(shade_shadowed(lights[0], penumbra[i], cut_options, bvh).diffuse - exact[i]) / open[i]);
  const double t_cuts = seconds_since(t) / std::max<std::size_t>(1, penumbra.size());
  std::printf("| method | samples per light | RMS error / unshadowed value | CPU µs per vertex | time / exact |\n|---|---|---|---|---|\n");
  std::printf("| exact, silhouettes (eq. 10, this work) | — | 0 (exact up to rounding) | %.1f | 1 |\n", 1e6 * t_exact);
  std::printf("| exact, triangle cuts | — | %.1e (largest, against silhouettes) | %.1f | %.2f |\n", cut_error, 1e6 * t_cuts,
              t_cuts / t_exact);
  std::mt19937_64 rng(3);
  for (int grid : {2, 4, 8, 16, 32, 64}) {
    if (quick && grid > 8) break;
    double err2 = 0;
    t = Clock::now();
    std::vector<double> est(penumbra.size());
    for (std::size_t i = 0; i < penumbra.size(); ++i) est[i] = shadow_ray_diffuse(scene.lights[0], penumbra[i], bvh, grid, rng);
    const double dt = seconds_since(t) / std::max<std::size_t>(1, penumbra.size());
    for (std::size_t i = 0; i < penumbra.size(); ++i) err2 += std::pow((est[i] - exact[i]) / open[i], 2);
    std::printf("| shadow rays | %d (2 triangles x %d x %d) | %.2e | %.1f | %.2f |\n", 2 * grid * grid, grid, grid,
                std::sqrt(err2 / std::max<std::size_t>(1, penumbra.size())), 1e6 * dt, dt / t_exact);
  }
  std::printf("\n");
}

// A unit square light at height 2 over a receiver grid at height 0, n x n vertices in [-1, 1]^2.
std::vector<ShadingPoint<double>> receivers(int n) {
  std::vector<ShadingPoint<double>> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      out.push_back(make_shading_point(Vec3d{-1 + 2.0 * (i + 0.5) / n, -1 + 2.0 * (j + 0.5) / n, 0}, Vec3d{0, 0, 1},
                                       Vec3d{0, 0, 5}, 10.0));
  return out;
}

// (a) Constant density: n triangles of size ~0.1 in a square of side sqrt(n)/10 * 2 at heights
// 0.2 .. 1.8; about the same number reach the light's volume whatever n.
std::vector<Tri> field(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  const double half = std::sqrt(double(n)) * 0.1;
  std::uniform_real_distribution<double> pos(-half, half), off(-0.05, 0.05), height(0.2, 1.8);
  std::vector<Tri> tris(n);
  for (Tri& t : tris) {
    const Vec3d c{pos(rng), pos(rng), height(rng)};
    t = {c + Vec3d{off(rng), off(rng), off(rng)}, c + Vec3d{off(rng), off(rng), off(rng)}, c + Vec3d{off(rng), off(rng), off(rng)}};
  }
  return tris;
}

// (b) A UV sphere of radius 0.3 at height 1 with about n triangles (closed: shared corners).
std::vector<Tri> sphere(std::size_t n) {
  const int rings = std::max(3, static_cast<int>(std::sqrt(n / 4.0)));
  const int segments = 2 * rings;
  auto point = [&](int i, int j) {
    const double theta = M_PI * i / rings, phi = 2 * M_PI * (j % segments) / segments;
    if (i == 0) return Vec3d{0, 0, 1.3};
    if (i == rings) return Vec3d{0, 0, 0.7};
    return Vec3d{0.3 * std::sin(theta) * std::cos(phi), 0.3 * std::sin(theta) * std::sin(phi), 1 + 0.3 * std::cos(theta)};
  };
  std::vector<Tri> tris;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const Vec3d a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
      if (i != 0) tris.push_back({a, b, d});
      if (i != rings - 1) tris.push_back({b, c, d});
    }
  return tris;
}

// The fastest of `repeat` runs of `loop`, in seconds.
template <class Loop>
double fastest_seconds(int repeat, const Loop& loop) {
  double best = 0;
  for (int r = 0; r < repeat; ++r) {
    const auto t = Clock::now();
    loop();
    const double dt = seconds_since(t);
    if (r == 0 || dt < best) best = dt;
  }
  return best;
}

void scaling(bool quick, int repeat, std::size_t min_triangles) {
  omp_set_num_threads(1);  // per-vertex costs of one thread, the clustered loop included
  LightSource l;
  l.type = LightType::kArea;
  l.name = "square";
  l.polygon = {{-0.5, -0.5, 2}, {-0.5, 0.5, 2}, {0.5, 0.5, 2}, {0.5, -0.5, 2}};
  const PreparedLight<double> light = prepare_light<double>(l);
  // A tube across the square's middle; both of its methods query the flat triangle (P, Q0, Q1).
  LightSource tube_source;
  tube_source.type = LightType::kLinear;
  tube_source.name = "tube";
  tube_source.from = {-0.5, 0, 2};
  tube_source.to = {0.5, 0, 2};
  const PreparedLight<double> tube = prepare_light<double>(tube_source);
  ShadeOptions o;
  o.with_specular = false;
  o.specular.method = SpecularMethod::kNone;
  const std::vector<ShadingPoint<double>> pts = receivers(quick ? 4 : 16);
  std::printf("## 3. Cost per vertex against the number of occluder triangles (%zu receiver vertices, one thread)\n\n",
              pts.size());
  for (int series = 0; series < 2; ++series) {
    std::printf("%s\n\n| triangles | BVH build (ms) | CPU µs per vertex (silhouettes) | CPU µs per vertex (silhouettes, "
                "clusters of %d) | CPU µs per vertex (triangle cuts) | cuts / silhouettes | largest difference / mean "
                "(clusters; cuts) | mean diffuse | CPU µs per vertex (tube, silhouettes) | CPU µs per vertex (tube, "
                "intervals) | intervals / silhouettes | largest difference / mean (tube) | mean diffuse (tube) |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
                series == 0 ? "(a) the scene grows (constant density field):" : "(b) one sphere, refined:",
                o.shadow_cluster_size);
    ShadeOptions cut_options = o;
    cut_options.area_shadows = AreaShadowMethod::kTriangleCuts;
    ShadeOptions interval_options = o;
    interval_options.linear_shadows = LinearShadowMethod::kTriangleIntervals;
    for (std::size_t n : {100ul, 1000ul, 10000ul, 100000ul, 1000000ul}) {
      if (quick && n > 1000) break;
      if (n < min_triangles) continue;
      const std::vector<Tri> tris = series == 0 ? field(n, 42) : sphere(n);
      auto t = Clock::now();
      // The sphere is one closed primitive: its back faces are skipped (occluder_triangles.h).
      const OccluderBvh bvh = series == 0 ? make_bvh(tris) : closed_bvh(tris);
      const double build = seconds_since(t);
      // One search per vertex: the fastest run's seconds per vertex, the diffuse of each and their mean.
      auto per_vertex_of = [&](const PreparedLight<double>& l, std::vector<double>& values, double& mean,
                               const ShadeOptions& with) {
        values.resize(pts.size());
        const double seconds = fastest_seconds(repeat, [&] {
          for (std::size_t i = 0; i < pts.size(); ++i) values[i] = shade_shadowed(l, pts[i], with, bvh).diffuse;
        });
        mean = 0;
        for (double v : values) mean += v;
        mean /= pts.size();
        return seconds / pts.size();
      };
      std::vector<double> value;
      double mean = 0;
      const double per_vertex = per_vertex_of(light, value, mean, o);
      // The vertex loop's path: one BVH search per cluster of neighbouring receivers (one thread).
      std::vector<Vec3d> clustered(pts.size());
      const double cluster_per_vertex = fastest_seconds(repeat, [&] {
        std::fill(clustered.begin(), clustered.end(), Vec3d{});
        accumulate_light_shadowed(light, o, pts.data(), static_cast<long>(pts.size()), clustered.data(), nullptr, bvh);
      }) / pts.size();
      double cluster_difference = 0;
      for (std::size_t i = 0; i < pts.size(); ++i)
        cluster_difference = std::max(cluster_difference, std::abs(clustered[i].x / light.radiance.x - value[i]));
      std::vector<double> tube_value, tube_interval_value;
      double tube_mean = 0, tube_interval_mean = 0;
      const double tube_per_vertex = per_vertex_of(tube, tube_value, tube_mean, o);
      const double tube_interval_per_vertex = per_vertex_of(tube, tube_interval_value, tube_interval_mean, interval_options);
      double tube_difference = 0;
      for (std::size_t i = 0; i < pts.size(); ++i)
        tube_difference = std::max(tube_difference, std::abs(tube_value[i] - tube_interval_value[i]));
      char tube_columns[160];
      std::snprintf(tube_columns, sizeof tube_columns, "%.1f | %.1f | %.1f | %.1e | %.6f", 1e6 * tube_per_vertex,
                    1e6 * tube_interval_per_vertex, tube_interval_per_vertex / tube_per_vertex,
                    tube_mean > 0 ? tube_difference / tube_mean : tube_difference, tube_mean);
      const bool cuts = series == 0 || n <= 10000;  // the cuts take ~0.5 s per vertex at 1e5 sphere triangles
      double cut_per_vertex = 0, difference = 0;
      if (cuts) {
        t = Clock::now();
        for (std::size_t i = 0; i < pts.size(); ++i)
          difference = std::max(difference, std::abs(shade_shadowed(light, pts[i], cut_options, bvh).diffuse - value[i]));
        cut_per_vertex = seconds_since(t) / pts.size();
      }
      if (cuts)
        std::printf("| %zu | %.1f | %.1f | %.1f | %.1f | %.1f | %.1e; %.1e | %.6f | %s |\n", tris.size(),
                    1e3 * build, 1e6 * per_vertex, 1e6 * cluster_per_vertex, 1e6 * cut_per_vertex,
                    cut_per_vertex / per_vertex, cluster_difference / mean, difference / mean, mean, tube_columns);
      else
        std::printf("| %zu | %.1f | %.1f | %.1f | — | — | %.1e; — | %.6f | %s |\n", tris.size(), 1e3 * build,
                    1e6 * per_vertex, 1e6 * cluster_per_vertex, cluster_difference / mean, mean, tube_columns);
      std::fflush(stdout);
    }
    std::printf("\n");
  }
}

}  // namespace
}  // namespace vlit::bench

int main(int argc, char** argv) {
  bool quick = false, with_cuts = true;
  int only = 0, repeat = 1;
  std::size_t min_triangles = 0;  // part 3 leaves out the smaller rows (to profile the large ones)
  std::vector<int> cluster_sizes;
  std::string scene = "assets/paper/bowling.glb", lights = "assets/paper/bowling-area.json";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") quick = true;
    else if (a == "--no-cuts") with_cuts = false;
    else if (a == "--only" && i + 1 < argc) only = std::atoi(argv[++i]);
    else if (a == "--repeat" && i + 1 < argc) {
      repeat = std::atoi(argv[++i]);
      if (repeat < 1) {
        std::fprintf(stderr, "shadow_bench: --repeat wants a positive integer\n");
        return 2;
      }
    }
    else if (a == "--min-triangles" && i + 1 < argc) {
      const long value = std::atol(argv[++i]);
      if (value < 1) {
        std::fprintf(stderr, "shadow_bench: --min-triangles wants a positive integer\n");
        return 2;
      }
      min_triangles = static_cast<std::size_t>(value);
    }
    else if (a == "--scene" && i + 1 < argc) scene = argv[++i];
    else if (a == "--lights" && i + 1 < argc) lights = argv[++i];
    else if (a == "--cluster-sizes" && i + 1 < argc) {
      std::istringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');) {
        const int size = std::atoi(item.c_str());
        if (size < 1) {
          std::fprintf(stderr, "shadow_bench: --cluster-sizes wants positive integers, as 16,64\n");
          return 2;
        }
        cluster_sizes.push_back(size);
      }
    } else {
      std::fprintf(stderr, "usage: shadow_bench [--quick] [--only 1|2|3] [--scene FILE --lights LIGHTS.json] [--no-cuts] "
                           "[--cluster-sizes N,N,...] [--repeat N] [--min-triangles N]\n");
      return 2;
    }
  }
  try {
    if (only == 0 || only == 1 || only == 2) vlit::bench::bowling(scene, lights, quick, only != 2, only != 1, with_cuts, cluster_sizes);
    if (only == 0 || only == 3) vlit::bench::scaling(quick, repeat, min_triangles);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadow_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
