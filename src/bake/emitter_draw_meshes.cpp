#include "bake/emitter_draw_meshes.h"

#include <cmath>
#include <numbers>

namespace vlit {
namespace {

Vec3d column(const Mat4d& m, int c) { return {m.m[0][c], m.m[1][c], m.m[2][c]}; }

// A convex polygon (counter-clockwise seen from its front) as a triangle fan: the front in
// `radiance`; behind it, unless two-sided, the same polygon wound the other way in black.
void add_polygon(const std::vector<Vec3d>& polygon, const Vec3d& radiance, bool two_sided,
                 std::vector<raster::DrawMesh>& out) {
  if (polygon.size() < 3) return;
  for (int side = 0; side < (two_sided ? 1 : 2); ++side) {
    raster::DrawMesh mesh;
    mesh.double_sided = two_sided;
    mesh.always_cull_back_faces = !two_sided;
    for (const Vec3d& p : polygon) {
      mesh.positions.push_back(static_cast<Vec3f>(p));
      mesh.colors.push_back(side == 0 ? static_cast<Vec3f>(radiance) : Vec3f{0, 0, 0});
    }
    for (std::uint32_t i = 1; i + 1 < polygon.size(); ++i)
      if (side == 0) mesh.indices.insert(mesh.indices.end(), {0, i, i + 1});
      else mesh.indices.insert(mesh.indices.end(), {0, i + 1, i});
    out.push_back(std::move(mesh));
  }
}

std::vector<Vec3d> disk_polygon(const LightSource& l) {
  const Vec3d n = normalize(l.normal);
  const Vec3d helper = std::abs(n.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  const Vec3d u = normalize(cross(helper, n)), v = cross(n, u);  // (u, v, n) right-handed: CCW seen from n
  constexpr int kSides = 48;
  std::vector<Vec3d> polygon;
  for (int i = 0; i < kSides; ++i) {
    const double a = 2 * std::numbers::pi * i / kSides;
    polygon.push_back(l.center + (u * std::cos(a) + v * std::sin(a)) * l.radius);
  }
  return polygon;
}

// Half the world-space width of a kTubePixels band at `point`.
double half_band_width(const Vec3d& point, const raster::Camera& camera, int image_height) {
  const double pixels_per_unit_height =
      camera.orthographic ? 2 * std::abs(camera.ymag)
                          : 2 * std::tan(0.5 * camera.yfov) * length(point - column(camera.world_from_camera, 3));
  return 0.5 * kTubePixels * pixels_per_unit_height / image_height;
}

void add_tube(const LightSource& l, const raster::Camera& camera, int image_height, std::vector<raster::DrawMesh>& out) {
  const double len = length(l.to - l.from);
  if (!(len > 0) || !std::isfinite(len)) return;
  const Vec3d eye = column(camera.world_from_camera, 3), back = normalize(column(camera.world_from_camera, 2));
  const Vec3d towards_eye = camera.orthographic ? back : eye - (l.from + l.to) * 0.5;
  Vec3d side = cross(l.to - l.from, towards_eye);
  if (!(length_squared(side) > 0)) side = cross(l.to - l.from, column(camera.world_from_camera, 1));  // seen end on
  if (!(length_squared(side) > 0)) return;
  side = normalize(side);
  const double w0 = half_band_width(l.from, camera, image_height), w1 = half_band_width(l.to, camera, image_height);
  raster::DrawMesh mesh;
  mesh.double_sided = true;
  mesh.positions = {static_cast<Vec3f>(l.from - side * w0), static_cast<Vec3f>(l.to - side * w1),
                    static_cast<Vec3f>(l.to + side * w1), static_cast<Vec3f>(l.from + side * w0)};
  mesh.colors.assign(4, static_cast<Vec3f>(l.color * (l.intensity / len)));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  out.push_back(std::move(mesh));
}

}  // namespace

std::vector<raster::DrawMesh> emitter_draw_meshes(const std::vector<LightSource>& lights, const raster::Camera& camera,
                                                  int image_height) {
  std::vector<raster::DrawMesh> out;
  for (const LightSource& l : lights) {
    if (l.emitting_primitive >= 0) continue;  // drawn as its primitive, with the material's emission
    const Vec3d radiance = l.color * l.intensity;
    if (l.type == LightType::kArea) add_polygon(l.polygon, radiance, l.two_sided, out);
    else if (l.type == LightType::kDisk) add_polygon(disk_polygon(l), radiance, l.two_sided, out);
    else if (l.type == LightType::kLinear) add_tube(l, camera, image_height, out);
  }
  return out;
}

}  // namespace vlit
