// Rendering to an image in memory: the shaded path of `vlit render` (src/cli/render_command.cpp):
// light every vertex with the specular seen from the camera, colour = kd x diffuse + ks x
// specular, rasterize. The debug views (wireframe, normals) stay on the command line.
#include <cmath>

#include "api/api_internal.h"
#include "bake/light_vertices.h"
#include "bake/lit_draw_mesh.h"
#include "gltf/gltf_file.h"
#include "raster/raster.h"
#include "raster/scene_camera.h"
#include "scene/material.h"

namespace vlit {
namespace {

// A look-at camera; throws Error(input, ...) when eye = target or up is parallel to the view.
raster::Camera camera_of(const View& view, const std::string& input) {
  const Vec3d eye = api::to_vec3d(view.eye);
  const Vec3d to_eye = eye - api::to_vec3d(view.target);
  const double distance = length(to_eye);
  if (!(distance > 0) || !std::isfinite(distance)) throw Error(input, "eye and target must differ and be finite", "settings.view");
  const Vec3d back = to_eye / distance;
  const Vec3d side = cross(api::to_vec3d(view.up), back);
  const double side_length = length(side);
  if (!(side_length > 1e-12) || !std::isfinite(side_length))
    throw Error(input, "up must not be parallel to the view direction", "settings.view.up");
  const Vec3d right = side / side_length;
  raster::Camera camera = raster::camera_from_frame(eye, right, cross(back, right), back);
  camera.yfov = view.yfov;
  camera.znear = std::max(1e-4 * distance, 1e-6);
  return camera;
}

Image render_scene(Scene& scene, const Lights& lights, const RenderSettings& settings, const std::string& input) {
  scene.lights.insert(scene.lights.end(), lights.impl().sources.begin(), lights.impl().sources.end());
  raster::RenderOptions options;
  options.width = settings.width;
  options.height = settings.height;
  options.samples = settings.samples;
  options.background = static_cast<Vec3f>(api::to_vec3d(settings.background));
  options.cull_back_faces = settings.cull_back_faces;
  if (const std::string problem = raster::validate_render_options(options); !problem.empty())
    throw Error(input, problem, "settings");

  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& p : scene.primitives)
    for (const auto& v : p.positions) { lo = min(lo, v); hi = max(hi, v); }
  const double aspect = static_cast<double>(settings.width) / settings.height;
  raster::Camera camera = settings.view   ? camera_of(*settings.view, input)
                          : !scene.cameras.empty() ? raster::camera_from_scene(scene.cameras.front())
                                         : raster::frame_bounds(lo, hi, aspect);
  if (const std::string problem = raster::validate_camera(camera); !problem.empty()) {
    if (settings.view) throw Error(input, "camera unusable: " + problem, "settings.view");
    camera = raster::frame_bounds(lo, hi, aspect);  // as the command line does, after a warning
  }

  api::ThreadCount threads(settings.threads);
  LightingRequest request;
  request.eye = Vec3d{camera.world_from_camera.m[0][3], camera.world_from_camera.m[1][3], camera.world_from_camera.m[2][3]};
  request.progress = settings.progress;
  request.cancel = settings.cancel;
  request.shade.specular = api::shade_options(settings).specular;
  request.shadows = settings.shadows;
  const std::vector<VertexLight> light = light_scene_vertices(scene, request);
  if (api::cancelled(settings)) throw Cancelled(input);

  std::vector<raster::DrawMesh> meshes;
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    ScenePrimitive& prim = scene.primitives[i];
    meshes.push_back(lit_draw_mesh(prim, scene.material_of(prim), light[i], std::move(prim.triangles)));
  }
  raster::Image image = raster::render(meshes, camera, options);
  Image out;
  out.width = image.width;
  out.height = image.height;
  out.rgb = std::move(image.rgb);
  return out;
}

}  // namespace

Image render(const tinygltf::Model& model, const Lights& lights, const RenderSettings& settings, const std::string& name) {
  return api::translate_errors(name, [&] {
    api::check_settings(settings, name);
    check_decodable(model, name);
    GltfFile file;  // the scene builder reads a GltfFile; the caller's model stays untouched
    file.path = name;
    file.model = model;
    std::vector<std::string> warnings;
    Scene scene = build_scene(file, warnings, {api::scene_limits(settings), settings.file_lights});
    file.model = tinygltf::Model();  // the buffers are not needed any more
    return render_scene(scene, lights, settings, name);
  });
}

Image render(const std::vector<Mesh>& meshes, const Lights& lights, const RenderSettings& settings) {
  return api::translate_errors("meshes", [&] {
    api::check_settings(settings, "meshes");
    Scene scene = api::scene_of_meshes(meshes);
    return render_scene(scene, lights, settings, "meshes");
  });
}

std::vector<std::uint8_t> to_srgb8(const Image& image, double exposure) {
  raster::Image linear;
  linear.width = image.width;
  linear.height = image.height;
  linear.rgb = image.rgb;
  if (linear.rgb.size() != 3 * std::size_t(std::max(image.width, 0)) * std::size_t(std::max(image.height, 0)))
    throw Error("image", "rgb holds " + std::to_string(image.rgb.size()) + " floats, not 3 x width x height");
  return raster::encode_srgb8(linear, static_cast<float>(exposure));
}

void save_png(const Image& image, const std::string& path, double exposure) {
  const std::vector<std::uint8_t> rgb8 = to_srgb8(image, exposure);
  std::string error;
  if (!raster::write_png(path, image.width, image.height, rgb8, &error)) throw Error(path, error);
}

}  // namespace vlit
