// vlit probe --lights LIGHTS.json --points POINTS.csv [--specular exact|exact-no-falloff|peak|neighborhood:K|none]
//            [--precision double|float] [--occluders SCENE.gltf|glb [--snap-to-vertices]]
// A light meter: diffuse and specular (kd = ks = 1, scalar intensities, colours ignored) summed
// over all lights at each point, 17 significant digits. With --occluders, the triangles of SCENE
// (all meshes, transforms applied) hide the lights that cast shadows (docs/shadows.md); with
// --snap-to-vertices, a point a few rounding errors off a vertex is moved onto it
// (shadow/snap_to_vertices.h) and shaded as that vertex is in a bake, with the wedges that
// triangles across a crease hide from it (shadow/point_wedges.h).
#include <cstdio>
#include <iostream>
#include <optional>

#include "cli/commands.h"
#include "cli/usage_error.h"
#include "cli/specular_option.h"
#include "core/input_error.h"
#include "io/lights_json.h"
#include "io/points_csv.h"
#include "load/load_scene.h"
#include "shading/prepared_light.h"
#include "shadow/light_meter.h"
#include "shadow/point_wedges.h"
#include "shadow/snap_to_vertices.h"

namespace vlit::cli {
namespace {

struct ProbeArgs {
  std::string lights, points;
  std::string specular = "exact";
  std::string precision = "double";
  std::string occluders;
  bool snap_to_vertices = false;
};

template <class T>
void probe(const std::vector<LightSource>& sources, const std::vector<ProbePoint>& points, const ShadeOptions& options,
           const OccluderBvh* occluders, const PointWedges* wedges) {
  std::vector<PreparedLight<T>> lights;
  for (const auto& s : sources) lights.push_back(prepare_light<T>(s));
  std::printf("index,diffuse,specular\n");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ProbePoint& p = points[i];
    const ShadingPoint<T> sp = make_shading_point(static_cast<Vec3<T>>(p.position), static_cast<Vec3<T>>(p.normal),
                                                  static_cast<Vec3<T>>(p.eye), T(p.shininess));
    const auto [diffuse, specular] =
        light_meter(lights, sources, sp, options, occluders, wedges ? wedges->of(i) : std::span<const WedgeCone>{});
    std::printf("%zu,%.17g,%.17g\n", i, diffuse, specular);
  }
}

int run_probe(const ProbeArgs& args) {
  ShadeOptions options;
  options.specular = parse_specular(args.specular);
  options.with_specular = options.specular.method != SpecularMethod::kNone;
  // Options that do not go together: usage errors, before anything is read.
  if (args.snap_to_vertices && args.occluders.empty())
    throw UsageError(args.points + ": --snap-to-vertices needs --occluders (the vertices are theirs)");
  if (!args.occluders.empty() && args.precision == "float")
    throw UsageError(args.occluders + ": --occluders needs --precision double (shadows are computed in double)");
  const auto lights = read_lights_json(args.lights);
  auto points = read_points_csv(args.points);
  std::optional<OccluderBvh> occluders;
  std::optional<PointWedges> wedges;
  if (!args.occluders.empty()) {
    LoadedScene scene = load_scene(args.occluders, "", {SceneLimits{}, false});
    OccluderTriangles triangles = occluders_of(scene.scene);
    if (args.snap_to_vertices) {
      std::vector<Vec3d> positions, normals;
      for (const ProbePoint& p : points) {
        positions.push_back(p.position);
        normals.push_back(p.normal);
      }
      const SnapCount n = snap_to_vertices(triangles, positions);
      for (std::size_t i = 0; i < points.size(); ++i) points[i].position = positions[i];
      std::fprintf(stderr, "probe: %zu of %zu points on a vertex of %s", n.snapped, points.size(), args.occluders.c_str());
      if (n.ambiguous > 0) std::fprintf(stderr, "; %zu left alone (near several vertices)", n.ambiguous);
      std::fprintf(stderr, "\n");
      if (options.crease_wedges) wedges.emplace(scene.scene, positions, normals);
    }
    occluders.emplace(std::move(triangles));
  }
  if (args.precision == "float") probe<float>(lights, points, options, nullptr, nullptr);
  else probe<double>(lights, points, options, occluders ? &*occluders : nullptr, wedges ? &*wedges : nullptr);
  return 0;
}

}  // namespace

Runner add_probe_command(CLI::App& app) {
  auto args = std::make_shared<ProbeArgs>();
  CLI::App* cmd = app.add_subcommand("probe", "Print the diffuse and specular light of LIGHTS.json at the points of a CSV file.");
  cmd->add_option("--lights", args->lights, "LIGHTS.json (docs/lights-json.md)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--points", args->points, "CSV with header px,py,pz,nx,ny,nz,ex,ey,ez,m (position, normal, eye, shininess)")
      ->required()->check(CLI::ExistingFile);
  cmd->add_option("--specular", args->specular, "Specular: exact (default, the lobe integrated with the light's falloff, docs/conventions.md), "
                  "exact-no-falloff (the paper's eq. 6), peak or neighborhood:K (the lobe's maximum) or none");
  cmd->add_option("--precision", args->precision, "Kernel scalar type: double (default) or float")
      ->check(CLI::IsMember({"double", "float"}));
  cmd->add_option("--occluders", args->occluders,
                  "glTF/GLB (or OBJ, PLY, OFF, STL) whose triangles hide the lights (all meshes, transforms applied)")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--snap-to-vertices", args->snap_to_vertices,
                "With --occluders: a point within 1e-6 of the occluders' size of one of their vertices (and of no "
                "other) is moved exactly onto it (points written in single precision by another program), and "
                "shaded as that vertex is in a bake: triangles across a crease hide what they hide from the "
                "vertex whose normal is closest to the point's (docs/shadows.md)");
  cmd->footer("Output: index,diffuse,specular per point, kd = ks = 1, summed over all lights with their scalar intensity. "
              "With exact, the specular is Ip ∫ [L.N > 0] max(0, Rv.L̂)^m / |L|^n over the light (point, spot, "
              "linear; the area lights' solid-angle form), as docs/conventions.md defines it.");
  return [args] { return run_probe(*args); };
}

}  // namespace vlit::cli
