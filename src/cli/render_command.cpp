// vlit render IN --lights LIGHTS.json -o OUT.png [--width W --height H] [--samples N] ...
// Lights every vertex (diffuse and specular towards the camera), then rasterizes with Gouraud
// shading: vertex colour = kd x diffuse light + ks x specular light.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "bake/emitter_draw_meshes.h"
#include "bake/light_vertices.h"
#include "bake/lit_draw_mesh.h"
#include "bake/preview_draw_mesh.h"
#include "bake/specular_dominance.h"
#include "cli/camera_option.h"
#include "cli/commands.h"
#include "cli/openmp_wait_policy.h"
#include "cli/scene_args.h"
#include "cli/specular_option.h"
#include "cli/terminal.h"
#include "cli/vector_option.h"
#include "core/input_error.h"
#include "gltf/gltf_scene.h"
#include "raster/raster.h"
#include "raster/scene_camera.h"
#include "load/load_scene.h"

namespace vlit::cli {
namespace {

struct RenderArgs {
  std::string input, output;
  SceneArgs scene;  // --lights, --no-file-lights, --shadows, --explain, limits
  int width = 800, height = 600, samples = 4;
  double exposure = 1;
  std::vector<double> background{0, 0, 0};
  bool cull_back_faces = false;
  bool quiet = false;
  bool preview = false;
  bool show_lights = false;
  std::string specular = "exact";
  std::string view = "shaded";
  std::string camera;  // --camera: empty = the file's first camera
  double wire_width = raster::WireframeOptions{}.width;
  std::uint64_t max_pixels = std::uint64_t(1) << 26;  // 8192 x 8192: ~1 GB of image buffers
};

// The normals debug view's colour of a world-space normal: 0.5 n + 0.5 per channel, written to the
// PNG as is (no sRGB OETF): +X = (255, 128, 128), -X = (0, 128, 128), +Y = (128, 255, 128)...
Vec3f normal_view_color(const Vec3d& n) { return static_cast<Vec3f>(n * 0.5 + Vec3d{0.5, 0.5, 0.5}); }

// Meshes coloured by their interpolated world normals (no lighting). Takes the scene's triangle
// lists (moved, not copied).
std::vector<raster::DrawMesh> normal_view_meshes(Scene& scene) {
  std::vector<raster::DrawMesh> meshes;
  for (ScenePrimitive& prim : scene.primitives) {
    raster::DrawMesh mesh;
    mesh.double_sided = scene.material_of(prim).double_sided;
    mesh.indices = std::move(prim.triangles);
    mesh.positions.reserve(prim.positions.size());
    mesh.colors.reserve(prim.positions.size());
    for (std::size_t v = 0; v < prim.positions.size(); ++v) {
      mesh.positions.push_back(static_cast<Vec3f>(prim.positions[v]));
      mesh.colors.push_back(v < prim.normals.size() ? normal_view_color(prim.normals[v]) : Vec3f{0.5f, 0.5f, 0.5f});
    }
    meshes.push_back(std::move(mesh));
  }
  return meshes;
}

// Whether the scene is drawn as a glTF viewer shows a baked asset: asked (--preview), or a scene
// without lights (none in the file, no --lights) that has COLOR_0; says why and what is left out.
bool previews(const RenderArgs& args, const Scene& scene) {
  const bool has_colors = std::any_of(scene.primitives.begin(), scene.primitives.end(),
                                      [](const ScenePrimitive& p) { return !p.colors.empty(); });
  const bool preview = args.preview || (scene.lights.empty() && has_colors);
  if (preview && !args.preview && !args.quiet)
    std::fprintf(stderr, "%s: no lights, and COLOR_0: drawing COLOR_0 x base colour unlit, as a glTF viewer shows a baked "
                 "asset (--preview; pass --lights LIGHTS.json to light it)\n", args.input.c_str());
  if (preview && std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) { return m.base_color_texture; }))
    print_warning(args.input + ": base colour textures are not sampled; the preview shows COLOR_0 x baseColorFactor");
  if (scene.lights.empty() && !preview)
    print_warning(args.input + ": no lights (pass --lights LIGHTS.json); the image will be black");
  return preview;
}

// The rasterizer's options from the command line; a usage problem names the output.
raster::RenderOptions render_options(const RenderArgs& args) {
  raster::RenderOptions options;
  options.width = args.width;
  options.height = args.height;
  options.samples = args.samples;
  options.background = {static_cast<float>(args.background[0]), static_cast<float>(args.background[1]),
                        static_cast<float>(args.background[2])};
  options.cull_back_faces = args.cull_back_faces;
  options.wireframe.enabled = args.view == "wireframe";
  options.wireframe.width = args.wire_width;
  if (const std::string problem = raster::validate_render_options(options); !problem.empty())
    throw InputError(args.output, problem);
  return options;
}

// The file's camera that --camera names (or its first), else a 3/4 view framing the scene; an
// unusable camera is replaced by the framing view, with a warning.
raster::Camera render_camera(const RenderArgs& args, const Scene& scene) {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& p : scene.primitives)
    for (const auto& v : p.positions) { lo = min(lo, v); hi = max(hi, v); }
  const double aspect = static_cast<double>(args.width) / args.height;
  const std::optional<SceneCamera> chosen = choose_camera(scene, args.camera, args.input);
  raster::Camera camera = chosen ? raster::camera_from_scene(*chosen) : raster::frame_bounds(lo, hi, aspect);
  if (const std::string problem = raster::validate_camera(camera); !problem.empty()) {
    print_warning(args.input + ": camera unusable (" + problem + "); framing the scene instead");
    camera = raster::frame_bounds(lo, hi, aspect);
  }
  return camera;
}

int run_render(const RenderArgs& args) {
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const SpecularOptions specular = parse_specular(args.specular);
  auto t = Clock::now();
  if (std::uint64_t(args.width) * std::uint64_t(args.height) > args.max_pixels)
    throw InputError(args.output, std::to_string(args.width) + " x " + std::to_string(args.height) +
                                      " pixels exceed the limit of " + std::to_string(args.max_pixels) +
                                      " (raise it with --max-pixels)");
  SceneOptions scene_options = args.scene.scene_options();
  scene_options.vertex_colors = args.view != "normals";  // COLOR_0, for the preview
  LoadedScene loaded = load_scene(args.input, args.scene.lights, scene_options);
  for (const auto& w : loaded.warnings) print_warning(w);
  loaded.gltf.reset();  // the glTF document (with its buffers) is for bake's output, not needed here
  const Scene& scene = loaded.scene;
  const double load_seconds = since(t);
  const bool normals_view = args.view == "normals";
  const bool preview = !normals_view && previews(args, scene);

  const raster::RenderOptions options = render_options(args);
  const raster::Camera camera = render_camera(args, scene);

  double plan_seconds = 0, light_seconds = 0;
  std::optional<ScenePlan> plan;
  std::vector<raster::DrawMesh> meshes;
  if (normals_view) {
    meshes = normal_view_meshes(loaded.scene);
  } else if (preview) {
    for (ScenePrimitive& prim : loaded.scene.primitives)
      meshes.push_back(preview_draw_mesh(prim, scene.material_of(prim), std::move(prim.triangles)));
    for (raster::DrawMesh& mesh : emitter_draw_meshes(scene.lights, camera, args.height)) meshes.push_back(std::move(mesh));
  } else {
    Progress progress("lighting", args.input, !args.quiet);
    LightingRequest request;
    request.eye = Vec3d{camera.world_from_camera.m[0][3], camera.world_from_camera.m[1][3], camera.world_from_camera.m[2][3]};
    request.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
    request.shade.specular = specular;
    request.shadows = args.scene.shadows_on();
    t = Clock::now();
    plan = plan_lighting(scene, request);
    plan_seconds = since(t);
    for (const std::string& line : unreached_light_warnings(*plan, scene)) print_warning(args.input + ": " + line);
    t = Clock::now();
    const auto light = light_scene_vertices(scene, *plan, request);
    light_seconds = since(t);
    progress.finish();
    if (const std::string line = specular_dominance_warning(
            measure_specular_dominance(scene, light, *request.eye, args.exposure), plan->shade.specular);
        !line.empty() && plan->shade.with_specular)
      print_warning(args.input + ": " + line);
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
      const ScenePrimitive& prim = scene.primitives[i];
      // The triangles are not needed by the scene any more: moved into the mesh.
      meshes.push_back(lit_draw_mesh(prim, scene.material_of(prim), light[i], std::move(loaded.scene.primitives[i].triangles)));
    }
    if (args.show_lights)
      for (raster::DrawMesh& mesh : emitter_draw_meshes(scene.lights, camera, args.height)) meshes.push_back(std::move(mesh));
  }
  // The scene's geometry is not needed any more: free it before rasterizing, where a large render
  // peaks (docs/rasterizer.md, memory).
  const std::string plan_text = args.scene.explain && plan ? describe(*plan, scene) : std::string(preview ? "plan: none (preview, unlit)\n" : "plan: none (normals view)\n");
  for (ScenePrimitive& prim : loaded.scene.primitives) {
    std::vector<Vec3d>().swap(prim.positions);
    std::vector<Vec3d>().swap(prim.normals);
    std::vector<Vec3f>().swap(prim.colors);
  }
  t = Clock::now();
  raster::RenderWorkspace workspace;
  raster::Image image;
  raster::render(meshes, camera, options, workspace, image);
  if (const std::size_t bad = workspace.bad_index_triangles())
    print_warning(args.input + ": " + std::to_string(bad) + " triangles skipped: an index beyond the mesh's vertices");
  const double raster_seconds = since(t);
  t = Clock::now();
  const std::vector<uint8_t> rgb8 =
      normals_view ? raster::encode_unorm8(image) : raster::encode_srgb8(image, static_cast<float>(args.exposure));
  std::string error;
  if (!raster::write_png(args.output, image.width, image.height, rgb8, &error)) throw InputError(args.output, error);
  if (args.scene.explain) {
    std::printf("%s\n%s%s\n", args.input.c_str(), plan_text.c_str(), openmp_threads_line().c_str());
    std::printf("time: load %.3f s, plan %.3f s, light %.3f s, rasterize %.3f s, encode+write %.3f s\n", load_seconds,
                plan_seconds, light_seconds, raster_seconds, since(t));
  }
  if (!args.quiet)
    std::fprintf(stderr, "rendered %zu triangles, %dx%d, %d samples per pixel, into %s\n",
                 [&] { std::size_t n = 0; for (const auto& m : meshes) n += m.indices.size() / 3; return n; }(),
                 image.width, image.height, args.samples, args.output.c_str());
  return 0;
}

}  // namespace

Runner add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Light every vertex and rasterize with Gouraud shading to an sRGB PNG.");
  // A missing input is an input that cannot be read (exit 1, like bake), not a usage error.
  cmd->add_option("input", args->input, "Input asset: glTF (.gltf, .glb), OBJ, PLY, OFF or STL")->required();
  cmd->add_option("-o,--output", args->output, "Output PNG (FILE.png); written atomically")
      ->required()
      ->check(CLI::Validator(
          [](const std::string& path) {
            std::string ext = std::filesystem::path(path).extension().string();
            for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            return ext == ".png" ? std::string()
                                 : "\"" + path + "\": render writes PNG images only; name the output FILE.png";
          },
          "FILE.png"));
  add_scene_options(*cmd, args->scene);
  cmd->add_option("--width", args->width, "Image width in pixels (default 800)")->check(CLI::Range(1, 16384));
  cmd->add_option("--height", args->height, "Image height in pixels (default 600)")->check(CLI::Range(1, 16384));
  cmd->add_option("--samples", args->samples, "Samples per pixel for anti-aliasing: 1, 4 (default), 16, 64")
      ->check(CLI::IsMember({1, 4, 9, 16, 25, 36, 49, 64}));
  cmd->add_option("--exposure", args->exposure, "Multiplier applied before sRGB encoding (default 1)")->check(CLI::PositiveNumber);
  add_vector3_option(*cmd, "--background", args->background, "Background color, linear RGB: R,G,B or R G B (default 0,0,0)");
  cmd->add_flag("--cull-back-faces", args->cull_back_faces, "Skip back faces of single-sided materials");
  cmd->add_option("--specular", args->specular,
                  "Specular: exact (default, the lobe integrated with the light's falloff), exact-no-falloff (the paper's "
                  "eq. 6), peak or neighborhood:K (the lobe's maximum over linear and area lights; fast) or none");
  cmd->add_option("--view", args->view,
                  "shaded (default); wireframe: triangle edges over the shading; normals: world normals as "
                  "colours, 0.5 n + 0.5, unlit, written without sRGB encoding or exposure (docs/rasterizer.md)")
      ->check(CLI::IsMember({"shaded", "wireframe", "normals"}));
  cmd->add_option("--wire-width", args->wire_width,
                  "Wireframe view: line width in pixels on each side of a shared edge (default 0.5)")
      ->check(CLI::Range(0.01, 64.0));
  cmd->add_flag("--preview", args->preview,
                "Draw what a glTF viewer shows for a baked, unlit asset: COLOR_0 x base colour (textures not "
                "sampled) plus emission, no lighting; panels, disks and tubes drawn with their own radiance. The "
                "default when the scene has no lights and has COLOR_0");
  cmd->add_flag("--show-lights", args->show_lights,
                "Also draw the lights that have a shape (panels, disks, tubes) with their own radiance in the lit "
                "render, as the preview does (off by default: the golden images show the lit surfaces only)");
  cmd->add_option("--camera", args->camera,
                  "The glTF camera to draw from: its index in the file's cameras, its name, or auto (a 3/4 view "
                  "framing the scene, whatever the file has); default: the file's first camera, else auto")
      ->type_name("INDEX|NAME|auto");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress or summary on stderr");
  cmd->add_option("--max-pixels", args->max_pixels, "Refuse an image larger than this many pixels (default 67108864)")
      ->check(CLI::PositiveNumber);
  cmd->footer("The camera is the glTF's first camera if it has one (or --camera), otherwise a 3/4 view framing the\n"
              "whole scene. The image's aspect (--width / --height) wins over the camera's aspectRatio: the vertical\n"
              "field of view is kept and the horizontal one follows the image, as in three.js.");
  return [args] { return run_render(*args); };
}

}  // namespace vlit::cli
