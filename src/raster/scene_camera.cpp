#include "raster/scene_camera.h"

namespace vlit::raster {

Camera camera_from_frame(const Vec3d& position, const Vec3d& right, const Vec3d& up, const Vec3d& back) {
  Camera out;
  Mat4d m = Mat4d::identity();
  const Vec3d cols[4] = {right, up, back, position};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 3; ++row) m.m[row][col] = cols[col][row];
  out.world_from_camera = m;
  return out;
}

Camera camera_from_scene(const SceneCamera& c) {
  Camera out = camera_from_frame(c.position, c.right, c.up, c.back);
  out.orthographic = c.orthographic;
  out.yfov = c.yfov;
  out.xmag = c.xmag;
  out.ymag = c.ymag;
  out.znear = c.znear;
  out.zfar = c.zfar;
  return out;
}

}  // namespace vlit::raster
