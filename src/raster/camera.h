// The camera the rasterizer renders from: a mirror of the glTF 2.0 camera object (so the glTF
// loader maps 1:1), its projection matrix, its validation, and a default camera that frames a
// bounding box for scenes that carry none.
#pragma once

#include <optional>
#include <string>

#include "core/mat4.h"
#include "core/vec3.h"

namespace vlit::raster {

struct Camera {
  Mat4d world_from_camera = Mat4d::identity();  // camera looks down its local -Z, +Y up (glTF)
  bool orthographic = false;
  double yfov = 0.8;             // perspective: vertical field of view, radians, in (0, pi)
  std::optional<double> aspect;  // perspective: width / height; absent = the image's width/height
  double xmag = 1, ymag = 1;     // orthographic half extents (camera units), nonzero
  double znear = 0.01;           // > 0 (perspective), >= 0 (orthographic)
  std::optional<double> zfar;    // absent = infinite perspective (glTF); required if orthographic
};

// Empty string if the camera can be rendered, else what is wrong (for the caller's error
// message). Checks what glTF requires: yfov in (0, pi), znear > 0 (perspective) / >= 0
// (orthographic), zfar > znear, zfar present for orthographic, xmag, ymag nonzero, aspect > 0,
// an invertible finite world_from_camera.
std::string validate_camera(const Camera& camera);

// clip_from_world = clip_from_camera * camera_from_world, with the image aspect used when the
// camera has none. Precondition: validate_camera(camera) is empty; otherwise returns nullopt
// when world_from_camera is singular.
std::optional<Mat4d> clip_from_world(const Camera& camera, double image_aspect);

// A perspective camera that frames the box [lo, hi] from a 3/4 view (from +X, +Y, +Z of the
// box centre, looking down about 25 degrees), yfov = 0.8, the given aspect (width/height), at the
// smallest distance where all eight corners are inside 90% of the image width and height, with
// znear/zfar bracketing the box. An empty or non-finite box frames the unit box at the origin, a
// point frames a unit box around it.
Camera frame_bounds(const Vec3d& lo, const Vec3d& hi, double aspect);

}  // namespace vlit::raster
