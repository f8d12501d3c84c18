#include <doctest/doctest.h>

#include <fstream>

#include "core/input_error.h"
#include "mesh/mesh_file.h"
#include "load/load_scene.h"
#include "support/gltf_builder.h"

using namespace vlit;

TEST_CASE("an OBJ quad is read as two triangles with computed normals") {
  const auto dir = vlit::test::temp_dir("obj");
  const auto path = (dir / "quad.obj").string();
  std::ofstream(path) << "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nf 1 2 3 4\n";
  std::vector<std::string> warnings;
  const Scene s = load_mesh_file(path, warnings);
  REQUIRE(s.primitives.size() == 1);
  CHECK(s.primitives[0].positions.size() == 4);
  CHECK(s.primitives[0].triangles.size() == 6);
  for (const auto& n : s.primitives[0].normals) CHECK(n == Vec3d{0, 0, 1});
  CHECK(s.material_of(s.primitives[0]).metallic == 0);
}

TEST_CASE("unreadable or unsupported mesh files are errors naming the file") {
  const auto dir = vlit::test::temp_dir("obj-bad");
  const auto empty = (dir / "empty.obj").string();
  std::ofstream(empty) << "# nothing\n";
  CHECK_THROWS_WITH_AS(load_scene(empty, ""), doctest::Contains(empty.c_str()), InputError);
  const auto txt = (dir / "notes.txt").string();
  std::ofstream(txt) << "hello";
  CHECK_THROWS_WITH_AS(load_scene(txt, ""), doctest::Contains("unsupported file type"), InputError);
}
