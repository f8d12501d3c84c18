// Accuracy report, end to end against Blender Cycles (docs/accuracy.md): the comparison light set,
// reading the Cycles bakes of bench/blender_bake.py, matching them to the asset's vertices, and
// the errors of Cycles and of vlit's settings against vlit's reference bake of the same lights.
// Optional at run time: without Cycles results the report says Blender was not available.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "bake/light_vertices.h"
#include "scene/scene.h"

namespace vlit::bench {

// The axis-aligned box of every vertex of the scene: where the report places its lights.
inline std::pair<Vec3d, Vec3d> scene_box(const Scene& scene) {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& p : scene.primitives)
    for (const Vec3d& v : p.positions) {
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
  return {lo, hi};
}

// Lights Cycles can represent (bench/blender_bake.py): linear lights of falloff 2, a rectangular
// area light, a point light; placed around the asset's bounding box like the end-to-end set.
inline std::vector<LightSource> blender_comparison_lights(const Scene& scene) {
  const auto [lo, hi] = scene_box(scene);
  const Vec3d c = (lo + hi) * 0.5;
  const double s = length(hi - lo) * 0.5;
  std::vector<LightSource> lights;
  auto linear = [&](const char* name, Vec3d a, Vec3d b) {
    LightSource l;
    l.type = LightType::kLinear;
    l.name = name;
    l.from = c + a * s;
    l.to = c + b * s;
    lights.push_back(l);
  };
  linear("tube above", {-1.2, 1.3, 0.8}, {1.2, 1.3, 0.8});
  linear("tube at the side", {1.6, -1, 0.4}, {1.6, 1.2, -0.2});
  LightSource panel;  // a 1.6 x 1.2 rectangle above, emitting downwards (counter-clockwise from below)
  panel.type = LightType::kArea;
  panel.name = "ceiling panel";
  for (Vec3d q : {Vec3d{0.8, 1.8, -0.6}, Vec3d{0.8, 1.8, 0.6}, Vec3d{-0.8, 1.8, 0.6}, Vec3d{-0.8, 1.8, -0.6}})
    panel.polygon.push_back(c + q * s);
  lights.push_back(panel);
  LightSource point;
  point.type = LightType::kPoint;
  point.name = "point front left";
  point.position = c + Vec3d{-1.5, 0.2, 1.4} * s;
  point.intensity = 0.5;
  lights.push_back(point);
  return lights;
}

inline std::string json_vec(const Vec3d& v) {
  char b[96];
  std::snprintf(b, sizeof b, "[%.17g, %.17g, %.17g]", v.x, v.y, v.z);
  return b;
}

// LIGHTS.json (docs/lights-json.md) of the comparison lights: read by vlit and by Blender.
inline std::string lights_json(const std::vector<LightSource>& lights) {
  std::ostringstream o;
  o << "{\"lights\": [\n";
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const LightSource& l = lights[i];
    o << "  {\"name\": \"" << l.name << "\", \"intensity\": " << l.intensity << ", ";
    if (l.type == LightType::kLinear)
      o << "\"type\": \"linear\", \"from\": " << json_vec(l.from) << ", \"to\": " << json_vec(l.to) << ", \"falloff\": 2";
    else if (l.type == LightType::kPoint)
      o << "\"type\": \"point\", \"position\": " << json_vec(l.position) << ", \"falloff\": 2";
    else {
      o << "\"type\": \"area\", \"polygon\": [";
      for (std::size_t k = 0; k < l.polygon.size(); ++k) o << (k ? ", " : "") << json_vec(l.polygon[k]);
      o << "]";
    }
    o << "}" << (i + 1 < lights.size() ? "," : "") << "\n";
  }
  o << "]}\n";
  return o.str();
}

// The same lights as Cycles sees them: each linear light as `points` point lights at the
// midpoints of equal pieces, intensity Ip / points each (bench/blender_bake.py).
// Points per linear light in Cycles' scene (bench/blender_bake.py LINEAR_POINTS).
inline constexpr int kCyclesTubePoints = 32;

inline std::vector<LightSource> as_point_chains(const std::vector<LightSource>& lights, int points) {
  std::vector<LightSource> out;
  for (const LightSource& l : lights) {
    if (l.type != LightType::kLinear) { out.push_back(l); continue; }
    for (int k = 0; k < points; ++k) {
      LightSource p;
      p.type = LightType::kPoint;
      p.position = l.from + (l.to - l.from) * ((k + 0.5) / points);
      p.intensity = l.intensity / points;
      out.push_back(p);
    }
  }
  return out;
}

struct CyclesRun {
  int samples = 0;
  double seconds = 0;
  std::vector<float> value;   // per scene vertex (concatenated primitives), NaN if unmatched
  std::size_t unmatched = 0;  // vertices no Cycles corner matched
};

struct CyclesData {
  bool available = false;
  std::string why_not;  // when not available
  double import_seconds = 0;
  std::string version = "unknown version";
  std::string calibration;  // calibration.txt, if present
  std::vector<CyclesRun> runs;
};

// Reads DIR/cycles-times.txt and DIR/cycles-S.txt and matches each Cycles corner to the scene
// vertex with (almost) the same position and normal; a vertex's value is the mean over its
// corners.
inline CyclesData read_cycles(const std::filesystem::path& dir, const Scene& scene) {
  CyclesData d;
  std::ifstream times(dir / "cycles-times.txt");
  if (!times) {
    d.why_not = "no Cycles results in `" + dir.string() + "`";
    return d;
  }
  if (std::ifstream v(dir / "blender-version.txt"); v) std::getline(v, d.version);
  if (std::ifstream cal(dir / "calibration.txt"); cal) {
    std::ostringstream s;
    s << cal.rdbuf();
    d.calibration = s.str();
  }
  // Vertex index: grid of cell size 1e-4 x the asset's size.
  struct V { Vec3d p, n; std::size_t index; };
  std::vector<V> verts;
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& prim : scene.primitives)
    for (std::size_t i = 0; i < prim.positions.size(); ++i) {
      verts.push_back({prim.positions[i], prim.normals[i], verts.size()});
      const Vec3d& v = prim.positions[i];
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
  const double cell = 1e-4 * std::max(length(hi - lo), 1e-30);
  auto key = [&](const Vec3d& p, int dx, int dy, int dz) {
    const long long x = std::llround(std::floor((p.x - lo.x) / cell)) + dx;
    const long long y = std::llround(std::floor((p.y - lo.y) / cell)) + dy;
    const long long z = std::llround(std::floor((p.z - lo.z) / cell)) + dz;
    return (x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL);
  };
  std::unordered_multimap<long long, std::size_t> grid;
  for (std::size_t i = 0; i < verts.size(); ++i) grid.emplace(key(verts[i].p, 0, 0, 0), i);

  std::string word;
  double value = 0;
  std::vector<std::pair<int, double>> bakes;
  while (times >> word >> value) {
    if (word == "import") d.import_seconds = value;
    else bakes.push_back({std::stoi(word), value});
  }
  for (const auto& [samples, seconds] : bakes) {
    std::ifstream f(dir / ("cycles-" + std::to_string(samples) + ".txt"));
    if (!f) continue;
    CyclesRun run;
    run.samples = samples;
    run.seconds = seconds;
    std::vector<double> sum(verts.size(), 0);
    std::vector<int> count(verts.size(), 0);
    Vec3d p, n;
    double r;
    while (f >> p.x >> p.y >> p.z >> n.x >> n.y >> n.z >> r) {
      // Every vertex at this position whose normal is the best match gets the value: glTF
      // vertices that differ only in their texture coordinates are one Blender vertex.
      double best = -1;
      std::vector<std::pair<double, std::size_t>> near;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            auto [a, b] = grid.equal_range(key(p, dx, dy, dz));
            for (auto it = a; it != b; ++it) {
              const V& v = verts[it->second];
              if (length(v.p - p) > cell) continue;
              const double score = dot(v.n, n);
              near.push_back({score, it->second});
              best = std::max(best, score);
            }
          }
      if (best > 0.99)
        for (const auto& [score, i] : near)
          if (score >= best - 1e-6) { sum[i] += r; ++count[i]; }
    }
    run.value.assign(verts.size(), NAN);
    for (std::size_t i = 0; i < verts.size(); ++i)
      if (count[i]) run.value[i] = float(sum[i] / count[i]);
      else ++run.unmatched;
    d.runs.push_back(std::move(run));
  }
  d.available = !d.runs.empty();
  if (!d.available) d.why_not = "`" + dir.string() + "/cycles-times.txt` lists no readable bake";
  return d;
}

// Error of per-vertex diffuse values (red channel; all lights are white) against a reference, as
// in the end-to-end table: max |Δ| / max |reference|, and the 99th percentile and median of
// |Δ| / max(|reference|, 1e-6 top). Vertices with a NaN value (unmatched) are left out.
struct DiffuseError {
  double max_rel_to_max = 0, p99_rel = 0, med_rel = 0;
  std::size_t vertices = 0;
};

inline DiffuseError diffuse_error(const std::vector<float>& value, const std::vector<float>& ref) {
  DiffuseError e;
  double top = 0;
  for (float r : ref) top = std::max(top, double(r));
  std::vector<double> rel;
  for (std::size_t i = 0; i < ref.size() && i < value.size(); ++i) {
    if (std::isnan(value[i])) continue;
    const double x = value[i], r = ref[i];
    e.max_rel_to_max = std::max(e.max_rel_to_max, std::fabs(x - r) / std::max(top, 1e-300));
    rel.push_back(std::fabs(x - r) / std::max(std::fabs(r), 1e-6 * top));
  }
  std::sort(rel.begin(), rel.end());
  e.vertices = rel.size();
  if (!rel.empty()) {
    e.med_rel = rel[rel.size() / 2];
    e.p99_rel = rel[std::min(rel.size() - 1, std::size_t(0.99 * double(rel.size())))];
  }
  return e;
}

inline std::vector<float> diffuse_red(const std::vector<VertexLight>& light) {
  std::vector<float> out;
  for (const auto& vl : light)
    for (const Vec3f& x : vl.diffuse) out.push_back(x.x);
  return out;
}

}  // namespace vlit::bench
