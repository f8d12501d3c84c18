// Generates assets/examples/file-lights.glb: a small room lit only by lights stored in the file
// (docs/gltf-lights.md): an EXT_lights_area rect panel and disk, a VLIT_lights_linear tube, an
// emissive line (LINES primitive) and an emissive quad (two triangles merged into one area
// light). Floor and back wall are tessellated grids. Usage: vlit_make_file_lights_scene OUT.glb
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/vec3.h"
#include "gltf_scene_writer.h"

namespace {

using vlit::MeshData;
using vlit::Vec3d;
using Value = tinygltf::Value;

using vlit::grid_mesh;

Value number(double x) { return Value(x); }
Value vec3(double x, double y, double z) { return Value(Value::Array{number(x), number(y), number(z)}); }

tinygltf::Node light_node(const std::string& name, const std::string& extension, int light, Vec3d translation,
                          std::vector<double> rotation) {
  tinygltf::Node n;
  n.name = name;
  n.translation = {translation.x, translation.y, translation.z};
  n.rotation = std::move(rotation);
  Value::Object ref;
  ref["light"] = Value(light);
  n.extensions[extension] = Value(ref);
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  return vlit::write_generated_scene(argc, argv, "generate_file_lights_scene", [](vlit::GltfSceneWriter& scene) {
    const int floor_mat = scene.material({"floor", {0.6, 0.6, 0.6}, 0.8, 0});
    const int wall_mat = scene.material({"wall", {0.8, 0.75, 0.7}, 0.9, 0});
    const int glow_line = scene.material({"neon", {1, 1, 1}, 1, 0, {0.2, 0.6, 1.0}, 0.3});
    const int glow_panel = scene.material({"glow panel", {1, 1, 1}, 1, 0, {1.0, 0.8, 0.5}, 0.5});
    scene.node("floor", scene.mesh("floor", {{grid_mesh({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 24, 24), floor_mat}}));
    scene.node("back wall", scene.mesh("back wall", {{grid_mesh({-3, 0, -3}, {6, 0, 0}, {0, 3, 0}, 24, 12), wall_mat}}));
    scene.node("neon", scene.line_mesh("neon", {{-2, 0.3, -2.9}, {2, 0.3, -2.9}}, glow_line));
    // Emissive quad under the ceiling facing down: counter-clockwise seen from below.
    MeshData quad;
    quad.positions = {{1.5, 2.9, 0.5}, {2.5, 2.9, 0.5}, {2.5, 2.9, 1.5}, {1.5, 2.9, 1.5}};
    quad.normals.assign(4, {0, -1, 0});
    quad.indices = {0, 1, 2, 0, 2, 3};
    scene.node("glow panel", scene.mesh("glow panel", {{quad, glow_panel}}));

    tinygltf::Model& model = scene.model();
    Value::Object rect, rect_shape, disk, area_root, tube, linear_root;
    rect["name"] = Value(std::string("ceiling panel"));
    rect["type"] = Value(std::string("rect"));
    rect["intensity"] = number(0.6);
    rect["size"] = number(0.8);
    rect_shape["aspect"] = number(2);
    rect["rect"] = Value(rect_shape);
    disk["name"] = Value(std::string("spot disk"));
    disk["type"] = Value(std::string("disk"));
    disk["intensity"] = number(0.8);
    disk["color"] = vec3(1, 0.85, 0.7);
    disk["size"] = number(0.5);
    area_root["lights"] = Value(Value::Array{Value(rect), Value(disk)});
    model.extensions["EXT_lights_area"] = Value(area_root);
    scene.uses("EXT_lights_area");
    tube["name"] = Value(std::string("tube"));
    tube["intensity"] = number(0.25);
    tube["color"] = vec3(1, 0.95, 0.9);
    tube["from"] = vec3(-1, 0, 0);
    tube["to"] = vec3(1, 0, 0);
    linear_root["lights"] = Value(Value::Array{Value(tube)});
    model.extensions["VLIT_lights_linear"] = Value(linear_root);
    scene.uses("VLIT_lights_linear");
    // Local -Z turned to world -Y: a rotation of -90 degrees about X.
    const std::vector<double> down = {-std::sqrt(0.5), 0, 0, std::sqrt(0.5)};
    scene.add_root_node(light_node("ceiling panel", "EXT_lights_area", 0, {-1, 2.95, 0}, down));
    scene.add_root_node(light_node("spot disk", "EXT_lights_area", 1, {1.5, 2.95, -1.5}, down));
    // Local -Z turned to world +Z (facing the room): the tube lies along world X on the wall.
    scene.add_root_node(light_node("wall tube", "VLIT_lights_linear", 0, {0, 1.8, -2.8}, {}));
    scene.camera({0, 1.6, 5.5}, {0, 1.0, 0}, 0.9, 4.0 / 3.0);
  });
}
