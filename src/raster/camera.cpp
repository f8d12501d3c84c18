// Camera validation, projection (glTF 2.0 matrices from core/mat4.h) and the default framing.
#include "raster/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vlit::raster {

std::string validate_camera(const Camera& camera) {
  const auto finite = [](double v) { return std::isfinite(v); };
  for (const auto& row : camera.world_from_camera.m)
    for (double v : row)
      if (!finite(v)) return "camera transform has a non-finite entry";
  if (!inverse(camera.world_from_camera)) return "camera transform is singular";
  if (camera.zfar && !(finite(*camera.zfar) && *camera.zfar > camera.znear))
    return "camera zfar must be finite and greater than znear";
  if (camera.orthographic) {
    if (!(finite(camera.xmag) && finite(camera.ymag) && camera.xmag != 0 && camera.ymag != 0))
      return "orthographic camera needs finite nonzero xmag and ymag";
    if (!(finite(camera.znear) && camera.znear >= 0)) return "orthographic camera needs znear >= 0";
    if (!camera.zfar) return "orthographic camera needs zfar (glTF requires it)";
  } else {
    if (!(finite(camera.yfov) && camera.yfov > 0 && camera.yfov < std::numbers::pi))
      return "perspective camera needs yfov in (0, pi) radians";
    if (!(finite(camera.znear) && camera.znear > 0)) return "perspective camera needs znear > 0";
    if (camera.aspect && !(finite(*camera.aspect) && *camera.aspect > 0))
      return "camera aspect ratio must be positive";
  }
  return {};
}

std::optional<Mat4d> clip_from_world(const Camera& camera, double image_aspect) {
  const std::optional<Mat4d> camera_from_world = inverse(camera.world_from_camera);
  if (!camera_from_world) return std::nullopt;
  const Mat4d clip_from_camera =
      camera.orthographic
          ? orthographic_gltf(camera.xmag, camera.ymag, camera.znear,
                              camera.zfar.value_or(camera.znear + 1.0))
          : perspective_gltf(camera.aspect.value_or(image_aspect), camera.yfov, camera.znear,
                             camera.zfar);
  return clip_from_camera * *camera_from_world;
}

Camera frame_bounds(const Vec3d& lo, const Vec3d& hi, double aspect) {
  const bool valid = is_finite(lo) && is_finite(hi) && lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z;
  const Vec3d center = valid ? (lo + hi) * 0.5 : Vec3d{};
  double radius = valid ? 0.5 * length(hi - lo) : 1.0;
  if (!(radius > 0) || !std::isfinite(radius)) radius = 1.0;

  Camera camera;
  camera.yfov = 0.8;
  if (std::isfinite(aspect) && aspect > 0) camera.aspect = aspect;
  const double a = camera.aspect.value_or(1.0);
  // The sphere fits if its angular radius is below the smaller half field of view.
  const double half_v = 0.5 * camera.yfov;
  const double half_h = std::atan(a * std::tan(half_v));
  const double half = std::min(half_v, half_h);
  const double distance = 1.05 * radius / std::sin(half);
  const Vec3d view_dir = normalize(Vec3d{1.0, 0.8, 1.6});  // from the centre towards the eye
  const Vec3d eye = center + view_dir * distance;
  camera.world_from_camera = look_at(eye, center, Vec3d{0, 1, 0});
  camera.znear = std::max(0.5 * (distance - radius), 1e-6 * distance);
  camera.zfar = 2.0 * (distance + radius);
  return camera;
}

}  // namespace vlit::raster
