// The camera the rasterizer renders from: a mirror of the glTF 2.0 camera object (so the glTF
// loader maps 1:1) without its aspect ratio, its projection matrix, its validation, and a default
// camera that frames a bounding box for scenes that carry none.
//
// The image's aspect wins over a perspective glTF camera's aspectRatio, as in three.js and other
// viewers that fit a camera to their canvas: yfov is kept and the horizontal field of view follows
// the image (docs/rasterizer.md "Conventions"). A file's aspectRatio would otherwise stretch every
// image whose width/height differs from it. An orthographic camera is drawn with its xmag and ymag
// as given (three.js's glTF loader does not refit those either).
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
  double xmag = 1, ymag = 1;     // orthographic half extents (camera units), nonzero
  double znear = 0.01;           // > 0 (perspective), >= 0 (orthographic)
  std::optional<double> zfar;    // absent = infinite perspective (glTF); required if orthographic
};

// Empty string if the camera can be rendered, else what is wrong (for the caller's error
// message). Checks what glTF requires: yfov in (0, pi), znear > 0 (perspective) / >= 0
// (orthographic), zfar > znear, zfar present for orthographic, xmag, ymag nonzero, an
// invertible finite world_from_camera.
std::string validate_camera(const Camera& camera);

// clip_from_world = clip_from_camera * camera_from_world for an image of aspect width/height:
// perspective with (image_aspect, yfov), orthographic with half extents (xmag, ymag). Precondition: validate_camera(camera) is empty; otherwise returns nullopt
// when world_from_camera is singular.
std::optional<Mat4d> clip_from_world(const Camera& camera, double image_aspect);

// A perspective camera that frames the box [lo, hi] from a 3/4 view (from +X, +Y, +Z of the
// box centre, looking down about 25 degrees), yfov = 0.8, for the given aspect (width/height), at the
// smallest distance where all eight corners are inside 90% of the image width and height, with
// znear/zfar bracketing the box. An empty or non-finite box frames the unit box at the origin, a
// point frames a unit box around it.
Camera frame_bounds(const Vec3d& lo, const Vec3d& hi, double aspect);

}  // namespace vlit::raster
