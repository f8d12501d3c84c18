// A glTF document for a scene read from a mesh file (OBJ, PLY, OFF, STL through OpenMesh), so
// `vlit bake` can store its light as COLOR_0 in a .glb/.gltf like for any glTF input.
#pragma once

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vlit {

// One node, mesh and TRIANGLES primitive per scene primitive (positions in float, already in
// world space; normals; 32-bit indices) and the scene's materials as metallic-roughness ones,
// with their names and emission (emissiveFactor, plus KHR_materials_emissive_strength above 1).
// Points each scene primitive at its glTF node, mesh and
// primitive (ScenePrimitive::node/mesh/primitive) so bake_vertex_colors can find it.
tinygltf::Model gltf_from_mesh_scene(Scene& scene);

}  // namespace vlit
