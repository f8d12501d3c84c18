// Accuracy report, end to end: a real asset lit by two linear and two area lights placed around
// its bounding box, under several settings (specular method, tolerances, float SIMD batch or
// scalar double, float kernels), errors per vertex against the reference setting; the COLOR_0
// encodings of the default bake; and the comparison with Blender Cycles (cycles_report.cpp).
// Returns the table and the numbers; the text around them is in docs/accuracy.md.in.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "accuracy_blender.h"
#include "bake/light_vertices.h"
#include "bake/vertex_color_bake.h"
#include "load/load_scene.h"
#include "report_format.h"
#include "reports.h"
#include "scene/material.h"

namespace vlit::bench::accuracy {

EndToEnd end_to_end(const Options& o) {
  EndToEnd e;
  if (o.asset.empty() || !fs::exists(o.asset)) {
    return e;
  }
  LoadedScene loaded = load_scene(o.asset, "", {SceneLimits{}, false});
  Scene& scene = loaded.scene;
  // Lights placed around the asset's bounding box.
  const auto [lo, hi] = scene_box(scene);
  const Vec3d c = (lo + hi) * 0.5;
  const double s = length(hi - lo) * 0.5;
  scene.lights.clear();
  auto linear = [&](Vec3d a, Vec3d b, double falloff, double intensity) {
    LightSource l;
    l.type = LightType::kLinear;
    l.from = c + a * s;
    l.to = c + b * s;
    l.falloff = falloff;
    l.intensity = intensity;
    scene.lights.push_back(l);
  };
  auto area = [&](std::vector<Vec3d> poly, double intensity) {
    LightSource l;
    l.type = LightType::kArea;
    for (const Vec3d& q : poly) l.polygon.push_back(c + q * s);
    l.intensity = intensity;
    scene.lights.push_back(l);
  };
  linear({-1.2, 1.3, 0.8}, {1.2, 1.3, 0.8}, 2, 1);      // tube above the front
  linear({1.6, -1, 0.4}, {1.6, 1.2, -0.2}, 1.5, 1);     // vertical tube at the side, falloff 1.5
  // Ceiling panel facing down: counter-clockwise seen from below (docs/lights-json.md).
  area({{0.8, 1.8, -0.8}, {0.8, 1.8, 0.8}, {-0.8, 1.8, 0.8}, {-0.8, 1.8, -0.8}}, 1);
  area({{-1.5, -0.6, 1.9}, {-0.3, -0.6, 1.9}, {-0.9, 0.6, 1.9}}, 1);                  // front triangle facing -z... flipped below
  std::reverse(scene.lights.back().polygon.begin(), scene.lights.back().polygon.end());
  const Vec3d eye = c + Vec3d{0.3, 0.4, 3} * s;

  struct Setting {
    std::string name;
    ShadeOptions shade;
    bool float_batch = true;  // LightingRequest::float_batch: diffuse-only lights in the float SIMD kernels
  };
  std::vector<Setting> settings;
  auto mk = [](SpecularMethod m, double spec_tol, double quad_tol, int k = 4) {
    ShadeOptions so;
    so.specular.method = m;
    so.specular.exact_tolerance = spec_tol;
    so.specular.neighborhood_samples = k;
    so.linear.quadrature_tolerance = quad_tol;
    return so;
  };
  settings.push_back({"reference: exact specular 1e-12, quadrature 1e-14", mk(SpecularMethod::kExact, 1e-12, 1e-14), false});
  settings.push_back({"peak specular, quadrature 1e-10", mk(SpecularMethod::kPeak, 1e-9, 1e-10)});
  settings.push_back({"default: exact specular 1e-9, quadrature 1e-10", mk(SpecularMethod::kExact, 1e-9, 1e-10)});
  settings.push_back({"fast exact: exact specular 1e-3, quadrature 1e-6", mk(SpecularMethod::kExact, 1e-3, 1e-6)});
  settings.push_back({"fast: peak specular, quadrature 1e-6", mk(SpecularMethod::kPeak, 1e-9, 1e-6)});
  settings.push_back({"diffuse only, quadrature 1e-6", mk(SpecularMethod::kNone, 1e-9, 1e-6)});
  // The same in the scalar double kernels: what the float SIMD batch kernels (the bake's default) cost and save.
  settings.push_back({"diffuse only, quadrature 1e-6, scalar double", mk(SpecularMethod::kNone, 1e-9, 1e-6), false});
  const std::size_t kBatchRow = settings.size() - 2, kDoubleRow = settings.size() - 1;

  omp_set_num_threads(1);
  std::vector<std::vector<VertexLight>> results;
  std::vector<double> seconds;
  for (const Setting& st : settings) {
    LightingRequest req;
    req.shade = st.shade;
    req.eye = eye;
    req.float_batch = st.float_batch;
    const auto t0 = std::chrono::steady_clock::now();
    results.push_back(light_scene_vertices(scene, req));
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    std::fprintf(stderr, "  end-to-end %-55s %.3f s\n", st.name.c_str(), seconds.back());
  }
  // Float: the library's scalar loop runs in double; the same per-vertex loop with the float kernels here.
  double float_seconds = 0;
  std::vector<VertexLight> float_result(scene.primitives.size());
  {
    std::vector<PreparedLight<float>> lights;
    for (const LightSource& l : scene.lights) lights.push_back(prepare_light<float>(l));
    const ShadeOptions so = settings[1].shade;
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t pi = 0; pi < scene.primitives.size(); ++pi) {
      const ScenePrimitive& prim = scene.primitives[pi];
      const float m = float(phong_from_metallic_roughness(scene.material_of(prim)).shininess);
      VertexLight& r = float_result[pi];
      r.diffuse.assign(prim.positions.size(), {});
      r.specular.assign(prim.positions.size(), {});
      for (std::size_t v = 0; v < prim.positions.size(); ++v) {
        const ShadingPoint<float> sp = make_shading_point(static_cast<Vec3f>(prim.positions[v]),
                                                          static_cast<Vec3f>(prim.normals[v]), static_cast<Vec3f>(eye), m);
        Vec3f d, sq;
        for (const PreparedLight<float>& l : lights) {
          const Response<float> x = shade(l, sp, so);
          d += l.radiance * x.diffuse;
          sq += l.radiance * x.specular;
        }
        r.diffuse[v] = d;
        r.specular[v] = sq;
      }
    }
    float_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  // COLOR_0 encodings of the default bake (what the colour format adds to the lighting error). A bake
  // without --specular-eye stores the diffuse only; specular would be folded into the colour.
  {
    std::vector<VertexLight> default_bake = results[1];
    for (VertexLight& vl : default_bake) vl.specular.clear();
    const struct { const char* name; ColorFormat format; int bytes; } kFormats[] = {
        {"unorm16", ColorFormat::kUnorm16, 8}, {"unorm8", ColorFormat::kUnorm8, 4}, {"float", ColorFormat::kFloat, 16}};
    for (const auto& f : kFormats) {
      tinygltf::Model model = loaded.gltf->model;
      BakeOptions bo;
      bo.format = f.format;
      const auto t0 = std::chrono::steady_clock::now();
      const BakeReport rep = bake_vertex_colors(model, scene, default_bake, bo);
      const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      e.formats.push_back({std::string(f.name) + (f.format == BakeOptions{}.format ? " (default)" : ""),
                           f.format == ColorFormat::kFloat ? 0.0 : rep.max_quantization_error, rep.clipped_vertices, sec,
                           f.bytes});
    }
    for (const auto& vl : results[1])
      for (const Vec3f& x : vl.diffuse) e.light_top = std::max(e.light_top, double(std::max({x.x, x.y, x.z})));
    e.default_seconds = seconds[1];
  }
  // Errors per vertex (luminance-free: the red channel; all lights are white) against the reference.
  struct Err { double max_rel_to_max = 0, p99_rel = 0, med_rel = 0; int nonfinite = 0; };
  auto compare = [&](const std::vector<VertexLight>& a, bool specular) {
    const auto& ref = results[0];
    double top = 0;
    for (const auto& vl : ref)
      for (const Vec3f& x : specular ? vl.specular : vl.diffuse) top = std::max(top, double(x.x));
    Err e;
    std::vector<double> rel;
    for (std::size_t pi = 0; pi < ref.size(); ++pi) {
      const auto& rv = specular ? ref[pi].specular : ref[pi].diffuse;
      const auto& av = specular ? a[pi].specular : a[pi].diffuse;
      if (av.size() != rv.size()) return Err{NAN, NAN, NAN, 0};
      for (std::size_t v = 0; v < rv.size(); ++v) {
        const double x = av[v].x, r = rv[v].x;
        if (!std::isfinite(x)) ++e.nonfinite;
        e.max_rel_to_max = std::max(e.max_rel_to_max, std::fabs(x - r) / std::max(top, 1e-300));
        rel.push_back(std::fabs(x - r) / std::max(std::fabs(r), 1e-6 * top));
      }
    }
    std::sort(rel.begin(), rel.end());
    if (!rel.empty()) {
      e.med_rel = rel[rel.size() / 2];
      e.p99_rel = rel[std::min(rel.size() - 1, size_t(0.99 * double(rel.size())))];
    }
    return e;
  };
  e.asset_name = fs::path(o.asset).filename().string();
  e.vertices = scene.vertex_count();
  for (const auto& p : scene.primitives) e.triangles += p.triangles.size() / 3;
  std::ostringstream md;
  md << "| setting | lighting time (s) | diffuse max/top | diffuse p99 rel | specular max/top | specular p99 rel |\n";
  md << "|---|---|---|---|---|---|\n";
  std::ofstream dat(o.out_dir / "data" / "end-to-end.dat");
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const Err d = compare(results[i], false);
    e.nonfinite += d.nonfinite;
    if (i == 1) e.diffuse_max_rel = d.max_rel_to_max;
    if (i == kBatchRow) e.batch = {d.max_rel_to_max, seconds[i]};
    if (i == kDoubleRow) e.scalar_double = {d.max_rel_to_max, seconds[i]};
    const bool has_spec = settings[i].shade.specular.method != SpecularMethod::kNone;
    const Err sp = has_spec ? compare(results[i], true) : Err{NAN, NAN, NAN, 0};
    e.nonfinite += sp.nonfinite;
    char t[32];
    std::snprintf(t, sizeof t, "%.3f", seconds[i]);
    md << "| " << settings[i].name << " | " << t << " | " << fmt(d.max_rel_to_max) << " | " << fmt(d.p99_rel) << " | "
       << fmt(sp.max_rel_to_max) << " | " << fmt(sp.p99_rel) << " |\n";
    if (i > 0)
      dat << "\"" << settings[i].name.substr(0, settings[i].name.find(':')) << "\" " << seconds[i] << " "
          << std::max(d.max_rel_to_max, kEndToEndZero) << " " << (has_spec ? std::max(sp.max_rel_to_max, kEndToEndZero) : NAN) << "\n";
  }
  {
    const Err d = compare(float_result, false), sp = compare(float_result, true);
    e.nonfinite += d.nonfinite + sp.nonfinite;
    char t[32];
    std::snprintf(t, sizeof t, "%.3f", float_seconds);
    md << "| default settings in float (own loop) | " << t << " | " << fmt(d.max_rel_to_max) << " | " << fmt(d.p99_rel)
       << " | " << fmt(sp.max_rel_to_max) << " | " << fmt(sp.p99_rel) << " |\n";
    dat << "\"float default\" " << float_seconds << " " << std::max(d.max_rel_to_max, kEndToEndZero) << " "
        << std::max(sp.max_rel_to_max, kEndToEndZero) << "\n";
  }
  e.table = md.str();
  e.cycles = cycles_comparison(o);
  std::ofstream gp(o.out_dir / "data" / "end-to-end.gp");
  gp << "set terminal pngcairo size 1000,600 font ',10'\nset output 'images/accuracy/end-to-end.png'\n"
        "set logscale xy\nset format y '1e%T'\nset grid\nset key top right\nset yrange [2e-10:*]\n"
        "set xlabel 'total lighting time, one thread (s)'\nset ylabel 'max |error| / max |reference| over the asset'\n"
        "set label 'error 0 (identical in float) drawn at 1e-9' at graph 0.02, first 4e-10 font ',8'\n"
        "set title 'End to end: "
     << fs::path(o.asset).filename().string()
     << ": error against lighting time'\n"
        "plot 'data/end-to-end.dat' using 2:3 with points pt 7 ps 1.5 title 'diffuse (COLOR_0)', \\\n"
        "     '' using 2:4 with points pt 5 ps 1.5 title 'specular', \\\n"
        "     '' using 2:3:1 with labels rotate by 30 offset 0.5,0.7 left font ',8' notitle"
     << e.cycles.plot << "\n";
  e.done = true;
  return e;
}

}  // namespace vlit::bench::accuracy
