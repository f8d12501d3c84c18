#include <doctest/doctest.h>

#include "core/input_error.h"
#include "io/lights_json.h"

using namespace vlit;

TEST_CASE("LIGHTS.json: every light type with defaults") {
  const auto lights = parse_lights_json(R"({"lights": [
    {"type": "point", "position": [1, 2, 3], "intensity": 2.5},
    {"type": "linear", "from": [0, 0, 0], "to": [1, 0, 0], "falloff": 1.5, "color": [1, 0.5, 0.25]},
    {"type": "area", "polygon": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "two_sided": true},
    {"type": "disk", "center": [0,0,1], "normal": [0,0,-2], "radius": 0.5},
    {"type": "directional", "direction": [0, 0, -3]},
    {"type": "spot", "position": [0,0,1], "direction": [0,0,-1], "outer_cone_angle": 0.5}
  ]})", "test.json");
  REQUIRE(lights.size() == 6);
  CHECK(lights[0].type == LightType::kPoint);
  CHECK(lights[0].falloff == 2);  // default
  CHECK(lights[0].intensity == 2.5);
  CHECK(lights[1].falloff == 1.5);
  CHECK(lights[1].color.y == 0.5);
  CHECK(lights[2].polygon.size() == 4);
  CHECK(lights[2].two_sided);
  CHECK(lights[3].normal.z == -1);  // normalized
  CHECK(lights[4].direction.z == -1);
  CHECK(lights[5].cos_outer == doctest::Approx(std::cos(0.5)));
}

TEST_CASE("LIGHTS.json errors name the file and the JSON pointer") {
  auto message = [](const std::string& text) {
    try {
      parse_lights_json(text, "lights.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message(R"({"lights": [{"type": "point"}]})") == "lights.json: /lights/0/position: missing required [x, y, z]");
  CHECK(message(R"({"lights": [{"type": "point", "position": [0,0,0], "falloff": 4}]})") ==
        "lights.json: /lights/0/falloff: falloff must be in [0, 3]");
  CHECK(message(R"({"lights": [{"type": "point", "position": [0,0,0], "intesity": 4}]})").find("/lights/0/intesity: unknown property") !=
        std::string::npos);
  CHECK(message(R"({"lights": [{"type": "laser"}]})").find("unknown light type \"laser\"") != std::string::npos);
  CHECK(message(R"({"lights": [{"type": "area", "polygon": [[0,0,0],[1,0,0],[2,0,0]]}]})") ==
        "lights.json: /lights/0/polygon: polygon has zero area");
  // Newell's normal of this quad is (1, -1, 2) / sqrt(6): vertices 1 and 3 lie 1 / sqrt(6) = 0.408
  // off the plane through vertex 0; its size (box diagonal) is sqrt(3), the tolerance 1e-6 of it.
  const std::string warped = message(R"({"lights": [{"type": "area", "polygon": [[0,0,0],[1,0,0],[1,1,0],[0,1,1]]}]})");
  CHECK(warped.rfind("lights.json: /lights/0/polygon: polygon is not planar: vertex ", 0) == 0);
  CHECK(warped.find(" is 0.408 off the plane of the polygon, more than the tolerance 1.73e-06 (1e-06 x its size 1.73)") !=
        std::string::npos);
  CHECK(message("{\"lights\": [\n  {\"type\": \"point\",,}\n]}").rfind("lights.json: line 2: invalid JSON", 0) == 0);
  CHECK(message(R"([1, 2])") == "lights.json: expected an object with a \"lights\" array");
  CHECK(message(R"({"lights": [{"type": "disk", "center": [0,0,0], "normal": [0,0,0], "radius": 1}]})") ==
        "lights.json: /lights/0/normal: direction has zero length");
}
