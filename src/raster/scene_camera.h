// The rasterizer's camera for a camera of the scene (a glTF camera node, world space): the frame
// (right, up, back) at its position, its projection as given.
#pragma once

#include "raster/raster.h"
#include "scene/scene.h"

namespace vlit::raster {

// world_from_camera with columns right, up, back, position.
Camera camera_from_frame(const Vec3d& position, const Vec3d& right, const Vec3d& up, const Vec3d& back);
Camera camera_from_scene(const SceneCamera& camera);

}  // namespace vlit::raster
