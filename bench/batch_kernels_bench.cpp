// Speed of the per-vertex diffuse kernels, and of an end-to-end bake, on 1 and 2 threads, from
// one process (docs/performance.md):
//
//   cmake --build build/release --target batch_kernels_bench -j2
//   ./build/release/bench/batch_kernels_bench --asset DamagedHelmet.glb   (any glTF; docs/performance.md)
//
// Part 1, kernels: vertex x light evaluations per second of each diffuse kernel, three ways:
// the scalar double kernel (the bake's path before the batch kernels), the same kernel
// instantiated in float, and the float SIMD batch kernel (stiff lanes recomputed in double, as
// in the bake: by the scalar double kernel, or inside the area kernel by its own double lanes).
// Each on one thread and on two. The shading points are a bake-like set: a floor
// of 2^16 points on a jittered grid in row order (normals tilted up to ~35 degrees) under the light. Also printed: the batch
// kernel's max relative error against the double kernel on the same points, the fraction of lanes
// that are stiff (sent to the scalar double kernel / computed by the kernel's double lanes), and a
// machine limit: the kernel's per-lane float operation counts (divisions and square roots counted
// apart; counted in the source, see docs/performance.md; the double lanes are not in it) times this
// machine's measured throughput of each kind of operation in the same vector code. When the max
// error is above 1e-5, the worst lane (value, share of the largest, difference) goes to stderr.
//
// Part 2, end-to-end: the asset is instanced on a grid until it has --vertices vertices (default
// 1e6; written to a temporary .glb next to --out-dir, deleted afterwards), lit by 4 area and 4
// linear lights, and baked with bake_file (load / plan / light / encode / write), with the batch
// kernels and with the scalar double path, on 1 and 2 threads.
//
// Part 1b, specular: the exact specular of a quad (area_specular_batch.h, integer m), of a point
// light (punctual_specular_batch.h) and of the tube (linear_specular_batch.h, integer m) against
// the scalar exact kernel, per m.
//
// --only NAME-PART: only the kernels whose name contains it (e.g. "quad"), for profiling.
// --quick: small sizes and short timings (seconds), for the ctest entry that proves it runs.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "bake/bake_file.h"
#include "shading/batch_kernels.h"
#include "light_sources.h"

namespace {

using namespace vlit;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Best-of-3 rate (items per second) of fn(), each repeated until min_seconds have passed.
double rate(const std::function<void()>& fn, double items, double min_seconds) {
  double best = 0;
  for (int trial = 0; trial < 3; ++trial) {
    long reps = 0;
    const auto t = Clock::now();
    double elapsed = 0;
    do {
      fn();
      ++reps;
      elapsed = seconds_since(t);
    } while (elapsed < min_seconds);
    best = std::max(best, items * double(reps) / elapsed);
  }
  return best;
}

// ---- Machine limit: throughput of each kind of float operation in vectorised code --------------

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define BENCH_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define BENCH_CLONES
#endif

// Eight independent chains per lane so that latency is hidden; the arrays stay in L1.
constexpr int kOpLanes = 1024;
BENCH_CLONES void op_mul_add(float* __restrict x, int reps) {
  for (int r = 0; r < reps; ++r) {
#pragma omp simd
    for (int i = 0; i < kOpLanes; ++i) x[i] = x[i] * 0.999f + 0.001f;  // 2 operations
  }
}
BENCH_CLONES void op_div(float* __restrict x, const float* __restrict y, int reps) {
  for (int r = 0; r < reps; ++r) {
#pragma omp simd
    for (int i = 0; i < kOpLanes; ++i) x[i] = y[i] / x[i];
  }
}
BENCH_CLONES void op_sqrt(float* __restrict x, int reps) {
  for (int r = 0; r < reps; ++r) {
#pragma omp simd
    for (int i = 0; i < kOpLanes; ++i) x[i] = std::sqrt(x[i]) + 0.5f;  // sqrt + 1 add
  }
}

struct OpRates {
  double add_mul = 0, div = 0, sqrt = 0;  // lane operations per second, one thread
};

OpRates measure_op_rates(double min_seconds) {
  std::vector<float> x(kOpLanes, 1.5f), y(kOpLanes, 1.25f);
  OpRates r;
  const int reps = 64;
  r.add_mul = 2 * rate([&] { op_mul_add(x.data(), reps); }, double(kOpLanes) * reps, min_seconds);
  r.div = rate([&] { std::fill(x.begin(), x.end(), 1.5f); op_div(x.data(), y.data(), reps); }, double(kOpLanes) * reps, min_seconds);
  r.sqrt = rate([&] { op_sqrt(x.data(), reps); }, double(kOpLanes) * reps, min_seconds);  // add included, negligible
  return r;
}

// Per-lane operation counts of each batch kernel (counted in shaders_cpu/batch/; docs/performance.md).
struct OpCount {
  double simple;  // add, sub, mul, compare, select, conversion (double counted twice: half the lanes)
  double div, sqrt;
};

double limit_rate(const OpCount& c, const OpRates& r) {
  return 1 / (c.simple / r.add_mul + c.div / r.div + c.sqrt / r.sqrt);
}

// ---- Part 1: kernels -------------------------------------------------------------------------

struct PointSet {
  std::vector<double> px, py, pz;
  std::vector<float> nx, ny, nz;
  std::vector<ShadingPoint<double>> sp_d;
  std::vector<ShadingPoint<float>> sp_f;
  long size() const { return long(px.size()); }
};

// A jittered side x side grid over [-4, 4]^2 in row order, as a mesh's vertices come: neighbours
// in memory are neighbours in space, so a block of lanes sees the light alike.
PointSet floor_points(long side) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  PointSet s;
  for (long i = 0; i < side * side; ++i) {
    const double step = 8.0 / double(side);
    const Vec3d p{-4 + step * (double(i % side) + 0.5 + 0.4 * u(rng)), -4 + step * (double(i / side) + 0.5 + 0.4 * u(rng)),
                  0.2 * u(rng)};
    const Vec3d nn = normalize(Vec3d{0.7 * u(rng), 0.7 * u(rng), 1});
    s.px.push_back(p.x); s.py.push_back(p.y); s.pz.push_back(p.z);
    s.nx.push_back(float(nn.x)); s.ny.push_back(float(nn.y)); s.nz.push_back(float(nn.z));
    const Vec3d nf{s.nx.back(), s.ny.back(), s.nz.back()};
    s.sp_d.push_back({p, nf, {0, 0, 1}, 1});
    s.sp_f.push_back({Vec3f(p), Vec3f(nf), {0, 0, 1}, 1});
  }
  return s;
}

struct KernelCase {
  const char* name;
  LightSource light;
  OpCount ops;
};

ShadeOptions diffuse_only() {
  ShadeOptions o;
  o.with_specular = false;
  o.specular.method = SpecularMethod::kNone;
  return o;
}

void run_kernel(const KernelCase& kc, const PointSet& pts, const OpRates& ops, double min_seconds, const std::string& only) {
  if (std::string(kc.name).find(only) == std::string::npos) return;
  const ShadeOptions options = diffuse_only();
  const PreparedLight<double> light_d = prepare_light<double>(kc.light);
  const PreparedLight<float> light_f = prepare_light<float>(kc.light);
  const BatchChoice choice = batch_kernel_for(light_d, options);
  if (!choice.light) {
    std::printf("%s: no batch kernel (%s)\n", kc.name, choice.reason.c_str());
    return;
  }
  const long n = pts.size();
  std::vector<double> out_d(n);
  std::vector<float> out_f(n), out_b(n);
  std::vector<std::uint8_t> stiff(n), in_double(n);
  const BatchPoints bp{pts.px.data(), pts.py.data(), pts.pz.data(), pts.nx.data(), pts.ny.data(), pts.nz.data()};
  auto scalar_double = [&] {
    std::visit([&](const auto& k) {
#pragma omp parallel for schedule(static)
      for (long v = 0; v < n; ++v) out_d[v] = shade_kernel<double>(k, pts.sp_d[v], options).diffuse;
    }, light_d.kernel);
  };
  auto scalar_float = [&] {
    std::visit([&](const auto& k) {
#pragma omp parallel for schedule(static)
      for (long v = 0; v < n; ++v) out_f[v] = shade_kernel<float>(k, pts.sp_f[v], options).diffuse;
    }, light_f.kernel);
  };
  auto batch = [&] {
    constexpr long kBlock = 1024;  // as the bake (src/bake/batch_lighting.cpp)
#pragma omp parallel for schedule(static)
    for (long b = 0; b < (n + kBlock - 1) / kBlock; ++b) {
      const long begin = b * kBlock, end = std::min(n, begin + kBlock);
      evaluate_diffuse_batch(*choice.light, bp, begin, end, BatchOutput{out_b.data(), stiff.data(), in_double.data()});
      for (long v = begin; v < end; ++v)
        if (stiff[v]) out_b[v] = float(shade(light_d, pts.sp_d[v], options).diffuse);
    }
  };
  double r[3][2];
  for (int t = 1; t <= 2; ++t) {
    omp_set_num_threads(t);
    r[0][t - 1] = rate(scalar_double, double(n), min_seconds);
    r[1][t - 1] = rate(scalar_float, double(n), min_seconds);
    r[2][t - 1] = rate(batch, double(n), min_seconds);
  }
  // Accuracy of the batch result (after the stiff lanes' double recomputation) and stiff share.
  batch();
  scalar_double();
  double max_ref = 0, worst = 0;
  long flagged = 0, doubled = 0, worst_lane = 0;
  for (long v = 0; v < n; ++v) max_ref = std::max(max_ref, out_d[v]);
  for (long v = 0; v < n; ++v) {
    flagged += stiff[v];
    doubled += in_double[v];
    const double err = std::fabs(out_b[v] - out_d[v]) / std::max(std::fabs(out_d[v]), 1e-12 * max_ref);
    if (err > worst) worst = err, worst_lane = v;
  }
  const double limit = limit_rate(kc.ops, ops);  // one thread
  std::printf("| %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1fx | %.1fx | %.2g | %.1f%% / %.1f%% | %.0f | %.0f%% | %.0f%% |\n", kc.name,
              r[0][0] / 1e6, r[0][1] / 1e6, r[1][0] / 1e6, r[1][1] / 1e6, r[2][0] / 1e6, r[2][1] / 1e6, r[2][0] / r[0][0],
              r[2][1] / r[0][1], worst, 100.0 * double(flagged) / double(n), 100.0 * double(doubled) / double(n), limit / 1e6, 100 * r[2][0] / limit,
              100 * r[2][1] / (2 * limit));
  if (worst > 1e-5)  // above the float bar: say which lane, for the table's notes
    std::fprintf(stderr, "%s: worst lane %ld: batch %.9g, double %.9g (%.2g of the largest value), |difference| %.2g%s\n",
                 kc.name, worst_lane, double(out_b[worst_lane]), out_d[worst_lane], out_d[worst_lane] / max_ref,
                 std::fabs(double(out_b[worst_lane]) - out_d[worst_lane]), in_double[worst_lane] ? ", computed in double" : "");
  std::fflush(stdout);
}

// Specular (exact, with the falloff) of one light at shininess m: the scalar double kernel (the
// bake's path without a batch specular kernel: shade(), diffuse included, as the bake calls it) and
// the batch specular kernel with its flagged lanes recomputed by shade(), as in the bake
// (src/bake/batch_lighting.cpp). Eye above the floor, Rv per point.
void run_specular(const char* name, const LightSource& source, double m, const PointSet& pts, double min_seconds,
                  const std::string& only) {
  if (std::string(name).find(only) == std::string::npos) return;
  ShadeOptions options;  // exact specular, with the falloff
  const PreparedLight<double> light = prepare_light<double>(source);
  BatchChoice choice = batch_kernel_for(light, options);
  enable_area_specular_batch(choice, light);  // area lights: the kernel the plan does not choose
  if (!specular_batch_covers(choice, m)) {
    std::printf("%s m=%g: no batch specular kernel (%s)\n", name, m, choice.specular_reason.c_str());
    return;
  }
  const long n = pts.size();
  const Vec3d eye{0.5, -1, 4};
  std::vector<ShadingPoint<double>> sp(pts.sp_d);
  std::vector<double> rx(n), ry(n), rz(n), out_d(n), out_b(n);
  std::vector<std::uint8_t> stiff(n);
  for (long v = 0; v < n; ++v) {
    sp[v] = make_shading_point(sp[v].p, sp[v].n, eye, m);
    sp[v].n = pts.sp_d[v].n;  // the float normal the batch sees
    rx[v] = sp[v].rv.x; ry[v] = sp[v].rv.y; rz[v] = sp[v].rv.z;
  }
  const BatchPoints bp{pts.px.data(), pts.py.data(), pts.pz.data(), pts.nx.data(), pts.ny.data(), pts.nz.data(),
                       rx.data(), ry.data(), rz.data()};
  auto scalar = [&] {
#pragma omp parallel for schedule(static)
    for (long v = 0; v < n; ++v) out_d[v] = shade(light, sp[v], options).specular;
  };
  auto batch = [&] {
    constexpr long kBlock = 1024;
#pragma omp parallel for schedule(static)
    for (long b = 0; b < (n + kBlock - 1) / kBlock; ++b) {
      const long begin = b * kBlock, end = std::min(n, begin + kBlock);
      evaluate_specular_batch(choice, options.specular, m, bp, begin, end, {out_b.data(), stiff.data()});
      for (long v = begin; v < end; ++v)
        if (stiff[v]) out_b[v] = shade(light, sp[v], options).specular;
    }
  };
  double r[2][2];
  for (int t = 1; t <= 2; ++t) {
    omp_set_num_threads(t);
    r[0][t - 1] = rate(scalar, double(n), min_seconds);
    r[1][t - 1] = rate(batch, double(n), min_seconds);
  }
  batch();
  // The error column against the scalar kernel with its adaptive form (on the lanes its closed
  // forms refuse) at 1e-12 rather than the default 1e-9, so that it measures the batch kernel.
  ShadeOptions tight = options;
  tight.specular.exact_tolerance = 1e-12;
  for (long v = 0; v < n; ++v) out_d[v] = shade(light, sp[v], tight).specular;
  double max_ref = 0, worst = 0;
  long flagged = 0;
  for (long v = 0; v < n; ++v) max_ref = std::max(max_ref, out_d[v]);
  for (long v = 0; v < n; ++v) {
    flagged += stiff[v];
    worst = std::max(worst, std::fabs(out_b[v] - out_d[v]) / std::max(std::fabs(out_d[v]), 1e-12 * max_ref));
  }
  std::printf("| %s | %g | %.2f | %.2f | %.2f | %.2f | %.1fx | %.1fx | %.2g | %.1f%% |\n", name, m, r[0][0] / 1e6, r[0][1] / 1e6,
              r[1][0] / 1e6, r[1][1] / 1e6, r[1][0] / r[0][0], r[1][1] / r[0][1], worst, 100.0 * double(flagged) / double(n));
  std::fflush(stdout);
}

// The benchmark's tube (falloff n) above the floor.
LightSource linear(double falloff) { return test::linear_source({-1, -0.3, 1.5}, {1, 0.3, 1.6}, falloff); }

// ---- Part 2: end-to-end bake -----------------------------------------------------------------

// Writes `path`: the asset's first mesh instanced on a grid until the scene has >= vertices.
std::size_t write_instanced_asset(const std::string& asset, const std::string& path, std::size_t vertices,
                                  double& extent) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const bool ok = asset.size() > 4 && asset.substr(asset.size() - 4) == ".glb"
                      ? loader.LoadBinaryFromFile(&model, &err, &warn, asset)
                      : loader.LoadASCIIFromFile(&model, &err, &warn, asset);
  if (!ok || model.meshes.empty()) throw std::runtime_error(asset + ": cannot load (" + err + ")");
  std::size_t per_instance = 0;
  double size = 0;
  for (const auto& prim : model.meshes[0].primitives) {
    const auto& acc = model.accessors[prim.attributes.at("POSITION")];
    per_instance += acc.count;
    for (int k = 0; k < 3 && k < int(acc.maxValues.size()); ++k) size = std::max(size, acc.maxValues[k] - acc.minValues[k]);
  }
  const std::size_t instances = (vertices + per_instance - 1) / per_instance;
  const int side = int(std::ceil(std::sqrt(double(instances))));
  const double spacing = 1.2 * size;
  extent = side * spacing;
  tinygltf::Scene scene;
  model.nodes.clear();
  for (std::size_t i = 0; i < instances; ++i) {
    tinygltf::Node node;
    node.mesh = 0;
    node.translation = {(double(i % side) - 0.5 * (side - 1)) * spacing, 0, (double(i / side) - 0.5 * (side - 1)) * spacing};
    scene.nodes.push_back(int(model.nodes.size()));
    model.nodes.push_back(node);
  }
  model.scenes = {scene};
  model.defaultScene = 0;
  model.animations.clear();
  model.skins.clear();
  model.cameras.clear();
  if (!loader.WriteGltfSceneToFile(&model, path, true, true, false, true)) throw std::runtime_error(path + ": cannot write");
  return instances * per_instance;
}

// 4 area panels and 4 tubes over the grid (y up), a few metres above it.
void write_lights(const std::string& path, double extent) {
  const double h = 0.35 * extent, q = 0.25 * extent, s = 0.06 * extent;
  std::ofstream f(path);
  f << "{\"lights\": [\n";
  int i = 0;
  for (double x : {-q, q})
    for (double z : {-q, q}) {
      f << "  {\"type\": \"area\", \"intensity\": 4, \"polygon\": [[" << x - s << "," << h << "," << z - s << "], [" << x + s << ","
        << h << "," << z - s << "], [" << x + s << "," << h << "," << z + s << "], [" << x - s << "," << h << "," << z + s << "]]},\n";
      ++i;
    }
  for (int k = 0; k < 4; ++k) {
    const double z = (k - 1.5) * 0.5 * q;
    f << "  {\"type\": \"linear\", \"intensity\": " << extent << ", \"falloff\": 2, \"from\": [" << -2 * q << "," << 0.6 * h << "," << z
      << "], \"to\": [" << 2 * q << "," << 0.6 * h << "," << z + 0.1 * q << "]}" << (k < 3 ? ",\n" : "\n");
  }
  f << "]}\n";
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string asset, out_dir = ".", only;
  std::size_t vertices = 1000000;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") quick = true;
    else if (a == "--asset" && i + 1 < argc) asset = argv[++i];
    else if (a == "--out-dir" && i + 1 < argc) out_dir = argv[++i];
    else if (a == "--vertices" && i + 1 < argc) vertices = std::stoul(argv[++i]);
    else if (a == "--only" && i + 1 < argc) only = argv[++i];
    else {
      std::fprintf(stderr, "usage: batch_kernels_bench [--quick] [--only KERNEL-NAME-PART] [--asset GLTF] [--vertices N] [--out-dir DIR]\n");
      return 2;
    }
  }
  if (quick) vertices = std::min<std::size_t>(vertices, 50000);
  const double min_seconds = quick ? 0.01 : 0.3;
  std::printf("batch kernels: %s; threads: 1 and 2 (of %d)\n\n", batch_instruction_set(), omp_get_num_procs());

  omp_set_num_threads(1);
  const OpRates ops = measure_op_rates(min_seconds);
  std::printf("machine, one thread, float lanes/s: add/mul %.3g, div %.3g, sqrt %.3g\n\n", ops.add_mul, ops.div, ops.sqrt);

  const PointSet pts = floor_points(quick ? 64 : 256);
  const std::vector<KernelCase> cases = {
      // Linear: a part shared by all n (double set-up, clipping, frame; 215 / 3 / 4 since the
      // horizon crossing is -a/b) plus the n-specific forms: n=0 57 / 9 / 1 (float_log.h's
      // log1p: 34 / 2 / 0), n=1 111 / 9 / 0 (log1p 34 / 2, two atan2_upper 31 / 1 each).
      {"linear diffuse n=0", linear(0), {272, 12, 5}},
      {"linear diffuse n=1", linear(1), {326, 12, 4}},
      {"linear diffuse n=2", linear(2), {227, 5, 4}},
      {"linear diffuse n=3", linear(3), {327, 16, 4}},
      {"quad diffuse", test::area_source({{-0.5, -0.5, 2}, {-0.5, 0.5, 2}, {0.5, 0.5, 2.1}, {0.5, -0.5, 2.1}}), {1020, 19, 10}},
      {"triangle diffuse", test::area_source({{-0.5, -0.5, 2}, {-0.5, 0.5, 2}, {0.5, 0.0, 2.1}}), {830, 15, 8}},
      // the quad's area and tilt; lanes in double (counted twice); counts of the full-circle lanes only
      {"disk diffuse", test::disk_source({0, 0, 2.05}, {0.1, 0, -1}, 0.5642), {190, 6, 8}},
  };
  std::printf("| kernel | double 1T | double 2T | float 1T | float 2T | batch 1T | batch 2T | batch/double 1T | batch/double 2T | batch max rel.err | stiff lanes: scalar / in-kernel double | limit 1T | 1T of limit | 2T of 2x limit |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const KernelCase& kc : cases) run_kernel(kc, pts, ops, min_seconds, only);
  LightSource point, spot, sun;
  point.name = "point";
  point.position = {0.2, 0.1, 2};
  spot = point;
  spot.type = LightType::kSpot;
  spot.cos_inner = std::cos(0.5);
  spot.cos_outer = std::cos(0.9);
  sun.type = LightType::kDirectional;
  sun.direction = normalize(Vec3d{0.3, 0.2, -1});
  run_kernel({"point diffuse", point, {70, 4, 2}}, pts, ops, min_seconds, only);
  run_kernel({"spot diffuse", spot, {100, 4, 2}}, pts, ops, min_seconds, only);
  run_kernel({"directional diffuse", sun, {12, 0, 0}}, pts, ops, min_seconds, only);
  std::printf("(M evaluations/s; T = threads; limit = per-lane operation counts x this machine's op rates measured above)\n\n");

  std::printf("| specular kernel | m | scalar exact 1T | scalar exact 2T | batch 1T | batch 2T | batch/scalar 1T | batch/scalar 2T | batch max rel.err | flagged lanes |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  const LightSource quad = test::area_source({{-0.5, -0.5, 2}, {-0.5, 0.5, 2}, {0.5, 0.5, 2.1}, {0.5, -0.5, 2.1}});
  for (double m : {1.0, 2.0, 30.0, 100.0, 300.0, 1000.0}) run_specular("quad specular", quad, m, pts, min_seconds, only);
  for (double m : {1.0, 30.0, 100.0, 2.1472}) run_specular("point specular", point, m, pts, min_seconds, only);
  for (double m : {0.0, 1.0, 2.0, 30.0, 100.0, 200.0}) run_specular("linear specular", linear(2), m, pts, min_seconds, only);
  std::printf("(M evaluations/s; exact specular with the falloff; eye at (0.5, -1, 4); flagged lanes recomputed by the scalar kernel, in the batch's time; error against the scalar kernel at tolerance 1e-12)\n\n");

  if (asset.empty()) return 0;
  namespace fs = std::filesystem;
  fs::create_directories(out_dir);
  const std::string big = (fs::path(out_dir) / "bench-instanced.glb").string();
  const std::string lights = (fs::path(out_dir) / "bench-lights.json").string();
  const std::string baked = (fs::path(out_dir) / "bench-baked.glb").string();
  double extent = 0;
  const std::size_t total = write_instanced_asset(asset, big, vertices, extent);
  write_lights(lights, extent);
  std::printf("end-to-end bake: %s instanced to %zu vertices, 4 area + 4 linear lights\n\n", asset.c_str(), total);
  std::printf("| path | threads | load s | plan s | light s | encode s | write s | total s | light M vertex-lights/s |\n|---|---|---|---|---|---|---|---|---|\n");
  for (bool float_batch : {false, true})
    for (int t = 1; t <= 2; ++t) {
      omp_set_num_threads(t);
      BakeFileOptions options;
      options.lights_path = lights;
      options.float_batch = float_batch;
      const BakeFileResult r = bake_file(big, baked, options);
      const StageTimes& s = r.seconds;
      std::printf("| %s | %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f |\n", float_batch ? "float batch" : "scalar double", t,
                  s.load, s.plan, s.light, s.encode, s.write, s.load + s.plan + s.light + s.encode + s.write,
                  8.0 * double(total) / s.light / 1e6);
      std::fflush(stdout);
    }
  fs::remove(big);
  fs::remove(baked);
  fs::remove(lights);
  return 0;
}
