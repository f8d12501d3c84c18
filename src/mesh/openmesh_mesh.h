// The OpenMesh triangle mesh vlit reads mesh files into (mesh_file.cpp) and compares its normals
// with (bench/vertex_normals_compare.cpp): double-precision points, vertex and face normals.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace vlit {

struct OpenMeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Normal);
  FaceAttributes(OpenMesh::Attributes::Normal);
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

}  // namespace vlit
