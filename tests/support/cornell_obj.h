// A small Cornell-box-like OBJ + MTL written by the tests (no vendored file): a 2 x 2 x 2 box
// (y up) open at the front, floor split into 2 x 2 quads so its centre (1, 0, 1) is a vertex,
// red left wall, green right wall, white floor, ceiling and back wall (the white material used by
// two separate usemtl runs), and an emitter: a square of side kLightSide centred at
// (1, kLightHeight, 1) facing down (-y) with Ke = kLightKe.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace vlit::test {

constexpr double kLightSide = 0.5;
constexpr double kLightHeight = 1.9;
constexpr double kLightKe[3] = {5, 4, 3};

// The emitter's corners, counter-clockwise seen from below (the side it emits to).
inline const double kLightCorners[4][3] = {{0.75, 1.9, 0.75}, {1.25, 1.9, 0.75}, {1.25, 1.9, 1.25}, {0.75, 1.9, 1.25}};

// Writes DIR/cornell.obj (mtllib line as given) and, when `write_mtl`, DIR/cornell.mtl.
inline std::filesystem::path write_cornell_obj(const std::filesystem::path& dir, bool write_mtl = true,
                                               const std::string& mtllib_line = "mtllib cornell.mtl") {
  const auto obj = dir / "cornell.obj";
  std::ofstream o(obj);
  o << "# Cornell-box-like test scene\n" << mtllib_line << "\n";
  // Floor grid: vertices 1..9 at (x, 0, z), x, z in {0, 1, 2}; index = 1 + 3 * ix + iz.
  for (int ix = 0; ix < 3; ++ix)
    for (int iz = 0; iz < 3; ++iz) o << "v " << ix << " 0 " << iz << "\n";
  o << "vn 0 1 0\n";
  o << "usemtl white\n";
  for (int ix = 0; ix < 2; ++ix)
    for (int iz = 0; iz < 2; ++iz) {
      auto idx = [](int x, int z) { return 1 + 3 * x + z; };
      // (x, z), (x, z+1), (x+1, z+1), (x+1, z): counter-clockwise seen from +y.
      o << "f " << idx(ix, iz) << "//1 " << idx(ix, iz + 1) << "//1 " << idx(ix + 1, iz + 1) << "//1 "
        << idx(ix + 1, iz) << "//1\n";
    }
  // Left wall x = 0 (normal +x), red: vertices 10..13.
  o << "v 0 0 0\nv 0 2 0\nv 0 2 2\nv 0 0 2\nusemtl red\nf 10 11 12 13\n";
  // Right wall x = 2 (normal -x), green: vertices 14..17.
  o << "v 2 0 0\nv 2 0 2\nv 2 2 2\nv 2 2 0\nusemtl green\nf 14 15 16 17\n";
  // Ceiling y = 2 (normal -y) and back wall z = 0 (normal +z), white again: vertices 18..25,
  // the back wall with a negative (relative) index.
  o << "usemtl white\nv 0 2 0\nv 2 2 0\nv 2 2 2\nv 0 2 2\nf 18 19 20 21\n";
  o << "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nf -4 -3 -2 -1\n";
  // The emitter, a little below the ceiling: vertices 26..29.
  o << "usemtl light\n";
  for (const auto& c : kLightCorners) o << "v " << c[0] << " " << c[1] << " " << c[2] << "\n";
  o << "f 26 27 \\\n 28 29\n";  // a continued line
  if (write_mtl) {
    std::ofstream m(dir / "cornell.mtl");
    m << "# materials\nnewmtl white\nKd 0.73 0.73 0.73\nKs 0 0 0\nNs 10\nillum 2\n\n"
      << "newmtl red\nKd 0.65 0.05 0.05\nNs 100\nmap_Kd red.png\n\n"
      << "newmtl green\nKd 0.12 0.45 0.15\n\n"
      << "newmtl light\nKd 0.78 0.78 0.78\nKe " << kLightKe[0] << " " << kLightKe[1] << " " << kLightKe[2] << "\n";
  }
  return obj;
}

}  // namespace vlit::test
