#include <doctest/doctest.h>

#include "core/input_error.h"
#include "io/points_csv.h"

using namespace vlit;

TEST_CASE("points CSV: header, comments, blank lines, signs and exponents") {
  const auto points = parse_points_csv(
      "px,py,pz,nx,ny,nz,ex,ey,ez,m\n# a comment\n\n1,2,3,0,0,1,0,0,10,20\n-1e-3, +2 ,3.5,0,1,0,1,1,1,1\n", "p.csv");
  REQUIRE(points.size() == 2);
  CHECK(points[0].position == Vec3d{1, 2, 3});
  CHECK(points[0].shininess == 20);
  CHECK(points[1].position.x == -1e-3);
  CHECK(points[1].position.y == 2);
}

TEST_CASE("points CSV: bad rows name the line") {
  auto message = [](const std::string& text) {
    try {
      parse_points_csv(text, "p.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string header = "px,py,pz,nx,ny,nz,ex,ey,ez,m\n";
  CHECK(message("x,y\n") == "p.csv: line 1: expected the header px,py,pz,nx,ny,nz,ex,ey,ez,m");
  CHECK(message(header + "1,2,3\n") == "p.csv: line 2: expected 10 comma-separated numbers, found 3");
  CHECK(message(header + "0,0,0,0,0,1,0,0,1,1\n1,2,abc,0,0,1,0,0,1,1\n") ==
        "p.csv: line 3: column pz: \"abc\" is not a finite number");
  CHECK(message(header + "0,0,0,0,0,0,0,0,1,1\n") == "p.csv: line 2: normal has zero length");
  CHECK(message(header + "0,0,0,0,0,1,0,0,1,nan\n") == "p.csv: line 2: column m: \"nan\" is not a finite number");
  CHECK(message("") == "p.csv: empty file: expected the header px,py,pz,nx,ny,nz,ex,ey,ez,m");
}
