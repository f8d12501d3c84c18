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
  }
  return {};
}

std::optional<Mat4d> clip_from_world(const Camera& camera, double image_aspect) {
  const std::optional<Mat4d> camera_from_world = inverse(camera.world_from_camera);
  if (!camera_from_world) return std::nullopt;
  const Mat4d clip_from_camera =
      camera.orthographic
          ? orthographic_gltf(camera.xmag, camera.ymag, camera.znear, camera.zfar.value_or(camera.znear + 1.0))
          : perspective_gltf(image_aspect, camera.yfov, camera.znear, camera.zfar);
  return clip_from_camera * *camera_from_world;
}

Camera frame_bounds(const Vec3d& lo, const Vec3d& hi, double aspect) {
  const bool valid = is_finite(lo) && is_finite(hi) && lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z;
  const Vec3d center = valid ? (lo + hi) * 0.5 : Vec3d{};
  Vec3d half = valid ? (hi - lo) * 0.5 : Vec3d{1, 1, 1};
  const double radius = length(half);
  if (!(radius > 0) || !std::isfinite(radius)) half = {1, 1, 1};  // a point: frame a unit box

  Camera camera;
  camera.yfov = 0.8;
  const double tan_v = std::tan(0.5 * camera.yfov);
  const double tan_h = tan_v * (std::isfinite(aspect) && aspect > 0 ? aspect : 1.0);
  constexpr double kFill = 0.9;  // the box spans at most 90% of the width or height

  // Orientation first (from +X, +Y, +Z of the centre, looking down ~25 degrees), then the
  // smallest distance d at which every corner is in front of the camera and inside the frustum:
  // a corner at camera-space offset (x, y, z) from the centre sits at depth d - z and needs
  // |x| <= kFill tan_h (d - z) and |y| <= kFill tan_v (d - z).
  const Vec3d back = normalize(Vec3d{1.0, 0.8, 1.6});  // from the centre towards the eye
  const Mat4d orientation = look_at(back, Vec3d{}, Vec3d{0, 1, 0});
  const Vec3d right{orientation.m[0][0], orientation.m[1][0], orientation.m[2][0]};
  const Vec3d up{orientation.m[0][1], orientation.m[1][1], orientation.m[2][1]};
  double distance = 0;
  Vec3d offsets[8];
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3d o{corner & 1 ? half.x : -half.x, corner & 2 ? half.y : -half.y, corner & 4 ? half.z : -half.z};
    offsets[corner] = {dot(o, right), dot(o, up), dot(o, back)};
    const Vec3d& c = offsets[corner];
    distance = std::max({distance, c.z + std::abs(c.x) / (kFill * tan_h), c.z + std::abs(c.y) / (kFill * tan_v)});
  }
  double nearest = distance, farthest = distance;
  for (const Vec3d& c : offsets) {
    nearest = std::min(nearest, distance - c.z);
    farthest = std::max(farthest, distance - c.z);
  }
  camera.world_from_camera = look_at(center + back * distance, center, Vec3d{0, 1, 0});
  camera.znear = std::max(0.5 * nearest, 1e-6 * distance);
  camera.zfar = 2.0 * farthest;
  return camera;
}

}  // namespace vlit::raster
