// Missing vertex normals: vlit's own angle-weighted normals (src/mesh/vertex_normals.h) against
// OpenMesh's two vertex-normal methods, on the triangles of real assets, from one process:
//   - run time of each (ratio to ours),
//   - the angle between the normals (max and mean over vertices),
//   - the faces OpenMesh's half-edge mesh refuses (add_face returns an invalid handle for a
//     non-manifold configuration), whose vertices then get a wrong or zero normal.
// docs/conventions.md "Missing normals" quotes its output.
//
//   cmake --build build/release --target vertex_normals_compare
//   ./build/release/bench/vertex_normals_compare assets/samples/Box/Box.gltf [more .gltf/.glb ...]
//
// Each primitive is given to OpenMesh with the glTF's own vertices (no welding), so both respect
// the primitive's vertex split. OpenMesh "fast" = sum of unit face normals (uniform weights, so it
// depends on how a face is triangulated); "correct" = sum of corner cross products (area weights).
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <chrono>
#include <functional>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/robust_math.h"
#include "gltf/gltf_scene.h"
#include "mesh/openmesh_mesh.h"
#include "mesh/vertex_normals.h"

namespace {

using namespace vlit;

double seconds_of(const std::function<void()>& f, int repeats) {
  const auto t = std::chrono::steady_clock::now();
  for (int i = 0; i < repeats; ++i) f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count() / repeats;
}

struct OpenMeshResult {
  std::vector<Vec3d> fast, correct;
  std::size_t refused = 0;
};

OpenMeshResult openmesh_normals(const std::vector<Vec3d>& positions, const std::vector<std::uint32_t>& triangles) {
  TriMesh mesh;
  std::vector<TriMesh::VertexHandle> vh;
  vh.reserve(positions.size());
  for (const Vec3d& p : positions) vh.push_back(mesh.add_vertex({p.x, p.y, p.z}));
  OpenMeshResult r;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const auto a = vh[triangles[t]], b = vh[triangles[t + 1]], c = vh[triangles[t + 2]];
    if (a == b || b == c || a == c || !mesh.add_face(a, b, c).is_valid()) ++r.refused;
  }
  mesh.update_face_normals();
  mesh.update_vertex_normals();  // "fast"
  for (const auto& v : vh) {
    const auto n = mesh.normal(v);
    r.fast.push_back({n[0], n[1], n[2]});
    TriMesh::Normal c;
    mesh.calc_vertex_normal_correct(v, c);
    r.correct.push_back({c[0], c[1], c[2]});
  }
  return r;
}

struct AngleStats {
  double max = 0, sum = 0;
  std::size_t count = 0;
  void add(const Vec3d& a, const Vec3d& b) {
    if (length_squared(a) == 0 || length_squared(b) == 0) return;
    const double angle = angle_between(a, b) * 180 / M_PI;
    max = std::max(max, angle);
    sum += angle;
    ++count;
  }
};

void report(const std::string& name, const std::vector<Vec3d>& positions, const std::vector<std::uint32_t>& triangles) {
  const int repeats = positions.size() > 100000 ? 3 : 20;
  std::vector<Vec3d> ours;
  OpenMeshResult om;
  const double t_ours = seconds_of([&] { ours = angle_weighted_normals(positions, triangles); }, repeats);
  const double t_om = seconds_of([&] { om = openmesh_normals(positions, triangles); }, repeats);
  AngleStats fast, correct;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    fast.add(ours[v], om.fast[v]);
    correct.add(ours[v], om.correct[v]);
  }
  std::printf("| %s | %zu | %zu | %.3f | %.1f | %zu | %.2f / %.3f | %.2f / %.3f |\n", name.c_str(), positions.size(),
              triangles.size() / 3, t_ours * 1e3, t_om / t_ours, om.refused, fast.max,
              fast.count ? fast.sum / fast.count : 0.0, correct.max, correct.count ? correct.sum / correct.count : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
  omerr().disable();  // OpenMesh logs every refused face ("complex edge"); we count them instead
  std::printf("| input | vertices | triangles | ours ms | OpenMesh time / ours | faces OpenMesh refuses | "
              "angle to OpenMesh fast, max / mean (deg) | angle to OpenMesh correct, max / mean (deg) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (int i = 1; i < argc; ++i) {
    std::vector<std::string> warnings;
    const Scene scene = build_scene(load_gltf_file(argv[i]), warnings);
    std::vector<Vec3d> positions;
    std::vector<std::uint32_t> triangles;
    for (const auto& p : scene.primitives) {  // all primitives, vertex indices offset: no welding
      const auto base = static_cast<std::uint32_t>(positions.size());
      positions.insert(positions.end(), p.positions.begin(), p.positions.end());
      for (auto t : p.triangles) triangles.push_back(base + t);
    }
    std::string name = argv[i];
    name = name.substr(name.find_last_of('/') + 1);
    report(name, positions, triangles);
  }
  // Non-manifold inputs a glTF may hold: a fin (three triangles on one edge) and a triangle
  // drawn twice.
  const std::vector<Vec3d> fin = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  report("fin (3 triangles on one edge)", fin, {0, 1, 2, 1, 0, 3, 0, 1, 4});
  const std::vector<Vec3d> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  report("a quad with one triangle repeated", quad, {0, 1, 2, 0, 2, 3, 1, 2, 0});
  return 0;
}
