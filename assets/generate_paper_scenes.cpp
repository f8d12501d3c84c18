// Generates the scenes of Picott 1992 ("Extensions of the Linear and Area Lighting Models", IEEE
// CG&A): the bowling lane of figures 3, 4 and 7 and the studio of figure 9, each as a .glb with a
// camera, plus one LIGHTS.json per figure (spot, linear, area). Every vertex and every light comes
// from the formulas and dimensions below; nothing is typed as a vertex list.
//
// Usage: vlit_make_paper_scenes OUT_DIR
// writes OUT_DIR/{bowling,studio}.glb and OUT_DIR/{bowling,studio}-{spot,linear,area}.json.
// The output is deterministic (same bytes on every run of the same build); the golden suite checks
// that the committed files under assets/paper/ are exactly what this program writes.
//
// Units are metres, +Y up. Bowling dimensions are the USBC / World Bowling regulation ones:
// lane 41.5 in (1.054 m) wide, gutters 9.25 in wide, pins 15 in (38.1 cm) tall on 12 in centres in
// an equilateral triangle, ball 8.595 in (21.8 cm) in diameter, 34 3/16 in from the head pin to the
// pit. The pin profile is a monotone cubic (Fritsch-Carlson) spline through the regulation
// diameters at a few heights (USBC Equipment Specifications and Certification Manual, pin
// drawing: base 2.031 in, belly 4.766 in at 4.5 in, neck 1.797 in at 10 in, head 2.547 in at
// 13.5 in), closed by an elliptical crown up to 15 in.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/vec3.h"
#include "gltf_scene_writer.h"
#include "io/atomic_write.h"

namespace vlit {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInch = 0.0254;

// ---------------------------------------------------------------------------------------------
// Geometry: indexed triangle meshes with per-vertex normals.

struct SurfacePoint {
  Vec3d position, normal;
};

// A (nu x nv)-cell parametric surface f(u, v), u, v in [0, 1]. Each quad is split into two
// triangles wound counter-clockwise as seen from the side its vertex normals point to, so that
// back-face culling keeps the visible side whatever the parametrization's handedness.
MeshData surface(int nu, int nv, const std::function<SurfacePoint(double, double)>& f) {
  MeshData m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const SurfacePoint s = f(double(i) / nu, double(j) / nv);
      m.positions.push_back(s.position);
      m.normals.push_back(normalize(s.normal));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const std::uint32_t a = j * (nu + 1) + i, b = a + 1, c = a + (nu + 1) + 1, d = a + (nu + 1);
      const auto& p = m.positions;
      const auto& n = m.normals;
      // Cross product of the diagonals: the quad's normal, non-zero even where a and b merge at a pole.
      const Vec3d facing = cross(p[c] - p[a], p[d] - p[b]);
      if (dot(facing, n[a] + n[b] + n[c] + n[d]) >= 0)
        m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
      else
        m.indices.insert(m.indices.end(), {a, c, b, a, d, c});
    }
  return m;
}

// A flat (nu x nv)-cell grid over origin + s*u + t*v, facing cross(u, v).
MeshData grid(Vec3d origin, Vec3d u, Vec3d v, int nu, int nv) {
  const Vec3d n = normalize(cross(u, v));
  return surface(nu, nv, [&](double s, double t) { return SurfacePoint{origin + u * s + v * t, n}; });
}

// An axis-aligned box, each face a cells_per_metre-dense grid facing outwards.
MeshData box(Vec3d lo, Vec3d hi, double cells_per_metre) {
  const Vec3d e = hi - lo;
  auto cells = [&](double length) { return std::max(1, static_cast<int>(std::ceil(length * cells_per_metre))); };
  MeshData m;
  m.append(grid({lo.x, lo.y, hi.z}, {e.x, 0, 0}, {0, e.y, 0}, cells(e.x), cells(e.y)));    // +Z
  m.append(grid({hi.x, lo.y, lo.z}, {-e.x, 0, 0}, {0, e.y, 0}, cells(e.x), cells(e.y)));   // -Z
  m.append(grid({hi.x, lo.y, hi.z}, {0, 0, -e.z}, {0, e.y, 0}, cells(e.z), cells(e.y)));   // +X
  m.append(grid({lo.x, lo.y, lo.z}, {0, 0, e.z}, {0, e.y, 0}, cells(e.z), cells(e.y)));    // -X
  m.append(grid({lo.x, hi.y, hi.z}, {e.x, 0, 0}, {0, 0, -e.z}, cells(e.x), cells(e.z)));   // +Y
  m.append(grid({lo.x, lo.y, lo.z}, {e.x, 0, 0}, {0, 0, e.z}, cells(e.x), cells(e.z)));    // -Y
  return m;
}

// A profile curve in the (radius, height) half-plane, parameter s.
struct ProfilePoint {
  double r, y;
};
using Profile = std::function<ProfilePoint(double)>;

// The surface of revolution about +Y of profile(s), s in [s0, s1], with outward normals (the
// profile runs upwards, so the outward normal of its tangent (dr, dy) is (dy, -dr)). The tangent
// comes from central differences of the profile, clamped to the interval.
MeshData lathe(const Profile& profile, double s0, double s1, int rings, int segments) {
  const double ds = 1e-5 * (s1 - s0);
  return surface(segments, rings, [&](double u, double v) {
    const double s = s0 + (s1 - s0) * v;
    const ProfilePoint p = profile(s);
    const ProfilePoint a = profile(std::max(s0, s - ds)), b = profile(std::min(s1, s + ds));
    const double dr = b.r - a.r, dy = b.y - a.y;
    const double phi = 2 * kPi * u, c = std::cos(phi), sn = std::sin(phi);
    return SurfacePoint{{p.r * c, p.y, -p.r * sn}, {dy * c, -dr, -dy * sn}};
  });
}

MeshData sphere(Vec3d center, double radius, int rings, int segments) {
  MeshData m = lathe([&](double s) { const double a = kPi * (s - 0.5); return ProfilePoint{radius * std::cos(a), radius * std::sin(a)}; },
                     0, 1, rings, segments);
  for (Vec3d& p : m.positions) p += center;
  return m;
}

// A vertical cylinder's side (no caps) from y0 to y1 around (x, z).
MeshData cylinder(Vec3d base, double radius, double height, int rings, int segments) {
  MeshData m = lathe([&](double s) { return ProfilePoint{radius, height * s}; }, 0, 1, rings, segments);
  for (Vec3d& p : m.positions) p += base;
  return m;
}

// A horizontal disk facing +Y (normal_up) or -Y.
MeshData disk(Vec3d center, double radius, bool normal_up, int rings, int segments) {
  const Vec3d n{0, normal_up ? 1.0 : -1.0, 0};
  return surface(segments, rings, [&](double u, double v) {
    const double phi = 2 * kPi * u;
    return SurfacePoint{center + Vec3d{radius * v * std::cos(phi), 0, -radius * v * std::sin(phi)}, n};
  });
}

// A torus around +Y lying on y = center.y.
MeshData torus(Vec3d center, double major, double minor, int rings, int segments) {
  return surface(segments, rings, [&](double u, double v) {
    const double phi = 2 * kPi * u, theta = 2 * kPi * v;
    const Vec3d radial{std::cos(phi), 0, -std::sin(phi)};
    const Vec3d n = radial * std::cos(theta) + Vec3d{0, std::sin(theta), 0};
    return SurfacePoint{center + radial * major + n * minor, n};
  });
}

// ---------------------------------------------------------------------------------------------
// The bowling pin profile: a monotone cubic Hermite spline (Fritsch & Carlson 1980) through the
// regulation diameters, so the belly, neck and head are true extrema (zero slope) and the curve
// never overshoots between the control heights; an elliptical crown closes the head.

struct Knot {
  double height_in, diameter_in;
};
// USBC pin drawing (inches). The spline is evaluated in inches and scaled to metres.
constexpr std::array<Knot, 4> kPinKnots{{{0.0, 2.031}, {4.5, 4.766}, {10.0, 1.797}, {13.5, 2.547}}};
constexpr double kPinHeightIn = 15.0;
constexpr double kPinHeadTopIn = 13.5;  // where the crown starts (the head's widest circle)

double pin_radius_in(double y) {
  // The four knots: base, belly, neck, head.
  double ys[4], rs[4];
  for (int k = 0; k < 4; ++k) {
    ys[k] = kPinKnots[k].height_in;
    rs[k] = kPinKnots[k].diameter_in / 2;
  }
  // Fritsch-Carlson slopes: zero at a local extremum (the secants change sign), the harmonic mean
  // of the secants elsewhere; one-sided at the ends.
  double secant[3], slope[4];
  for (int k = 0; k < 3; ++k) secant[k] = (rs[k + 1] - rs[k]) / (ys[k + 1] - ys[k]);
  slope[0] = secant[0];
  slope[3] = 0;  // the head's widest circle
  for (int k = 1; k < 3; ++k)
    slope[k] = secant[k - 1] * secant[k] <= 0 ? 0 : 2 / (1 / secant[k - 1] + 1 / secant[k]);
  int k = 0;
  while (k < 2 && y > ys[k + 1]) ++k;
  const double h = ys[k + 1] - ys[k], t = std::clamp((y - ys[k]) / h, 0.0, 1.0);
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * rs[k] + (t3 - 2 * t2 + t) * h * slope[k] + (-2 * t3 + 3 * t2) * rs[k + 1] +
         (t3 - t2) * h * slope[k + 1];
}

// The whole pin, parameter s = height in inches for the body; past 13.5 in it runs around a
// quarter ellipse (semi-axes: head radius, 1.5 in) so the crown closes with a horizontal tangent.
ProfilePoint pin_profile(double s) {
  if (s <= kPinHeadTopIn) return {pin_radius_in(s) * kInch, s * kInch};
  const double a = (s - kPinHeadTopIn) / (kPinHeightIn - kPinHeadTopIn) * (kPi / 2);
  const double head = kPinKnots[3].diameter_in / 2;
  return {head * std::cos(a) * kInch, (kPinHeadTopIn + (kPinHeightIn - kPinHeadTopIn) * std::sin(a)) * kInch};
}

// ---------------------------------------------------------------------------------------------
// LIGHTS.json output (docs/lights-json.md), written by hand so the bytes are stable.

// Distance falloff n of the spots and tubes: 1, the "linear decay" of the renderers of the
// paper's time, not the physical 2. The paper's specular (eq. 6, and its linear and area forms)
// has no distance falloff, so with n = 2 the intensity needed to light a floor 3 m away makes the
// specular of even matte surfaces (ks = 0.04) as bright as their diffuse and washes the walls
// out; with n = 1 it stays a tenth of it. docs/paper-scenes.md.
constexpr int kFalloff = 1;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", std::abs(v) < 5e-5 ? 0.0 : v);
  return buf;
}
std::string vec(Vec3d v) { return "[" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + "]"; }
std::string rgb(std::array<double, 3> c) { return vec({c[0], c[1], c[2]}); }

class LightsJson {
 public:
  void spot(const std::string& name, Vec3d position, Vec3d target, double inner, double outer, double intensity,
            std::array<double, 3> color) {
    add("{\"name\": \"" + name + "\", \"type\": \"spot\", \"position\": " + vec(position) +
        ", \"direction\": " + vec(normalize(target - position)) + ",\n   \"inner_cone_angle\": " + num(inner) +
        ", \"outer_cone_angle\": " + num(outer) + ", \"intensity\": " + num(intensity) + ", \"falloff\": " + std::to_string(kFalloff) +
        ", \"color\": " + rgb(color) + "}");
  }
  void linear(const std::string& name, Vec3d from, Vec3d to, double intensity, std::array<double, 3> color) {
    add("{\"name\": \"" + name + "\", \"type\": \"linear\", \"from\": " + vec(from) + ", \"to\": " + vec(to) +
        ",\n   \"intensity\": " + num(intensity) + ", \"falloff\": " + std::to_string(kFalloff) +
        ", \"color\": " + rgb(color) + "}");
  }
  // A rectangle centred at c with edge vectors u and v; it emits towards cross(u, v), so its
  // corners c -/+ u/2 -/+ v/2 are listed counter-clockwise seen from that side.
  void panel(const std::string& name, Vec3d c, Vec3d u, Vec3d v, double intensity, std::array<double, 3> color) {
    const Vec3d hu = u * 0.5, hv = v * 0.5;
    add("{\"name\": \"" + name + "\", \"type\": \"area\", \"polygon\": [" + vec(c - hu - hv) + ", " + vec(c + hu - hv) +
        ", " + vec(c + hu + hv) + ", " + vec(c - hu + hv) + "],\n   \"intensity\": " + num(intensity) +
        ", \"two_sided\": false, \"color\": " + rgb(color) + "}");
  }
  void write(const std::string& path) const {
    std::string out = "{\"lights\": [\n";
    for (std::size_t i = 0; i < entries_.size(); ++i) out += "  " + entries_[i] + (i + 1 < entries_.size() ? ",\n" : "\n");
    out += "]}\n";
    write_file_atomically(path, out);
  }

 private:
  void add(std::string entry) { entries_.push_back(std::move(entry)); }
  std::vector<std::string> entries_;
};

// ---------------------------------------------------------------------------------------------
// Figures 3, 4, 7: the bowling lane. Head pin at the origin, the lane runs towards +Z (the
// bowler), the pit is at -Z. The lane surface is y = 0.

constexpr double kLaneWidth = 41.5 * kInch;        // 1.054 m
constexpr double kGutterWidth = 9.25 * kInch;      // 0.235 m, a half-cylinder trough
constexpr double kPinSpacing = 12 * kInch;         // centre to centre
constexpr double kPinDeckBack = -34.1875 * kInch;  // head pin centre to the pit edge
constexpr double kBallRadius = 8.595 * kInch / 2;  // 21.8 cm diameter
constexpr double kLaneNear = 6.0;                  // the modelled lane ends 6 m towards the bowler (behind the camera)
constexpr double kPitDepth = 0.25, kPitLength = 0.75, kBackWallHeight = 1.6;

constexpr std::array<double, 3> kWarmWhite{1.0, 0.93, 0.82};
constexpr std::array<double, 3> kCoolWhite{0.9, 0.95, 1.0};

bool write_bowling(const std::string& dir) {
  GltfSceneWriter w("vlit generate_paper_scenes (Picott 1992 fig. 3, 4, 7)");
  const auto [maple, gutter_grey, capping, dark, kickback, pin_white, pin_red, ball_blue] =
      w.materials({{"lane maple", {0.72, 0.5, 0.28}, 0.3, 0},
                   {"gutter", {0.12, 0.12, 0.13}, 0.45, 0},
                   {"capping", {0.12, 0.1, 0.09}, 0.6, 0},
                   {"pit and masking", {0.1, 0.1, 0.12}, 0.9, 0},
                   {"kickback", {0.35, 0.18, 0.12}, 0.7, 0},
                   {"pin white", {0.92, 0.91, 0.88}, 0.25, 0},
                   {"pin stripe", {0.75, 0.06, 0.05}, 0.25, 0},
                   {"ball", {0.08, 0.16, 0.55}, 0.12, 0}});

  const double half = kLaneWidth / 2, r_gutter = kGutterWidth / 2;
  const double lane_length = kLaneNear - kPinDeckBack;

  // Lane and pin deck: about 4.4 cm across, 5 cm along.
  w.node("lane", w.mesh("lane", {{grid({-half, 0, kLaneNear}, {kLaneWidth, 0, 0}, {0, 0, -lane_length}, 24,
                                        static_cast<int>(std::round(lane_length / 0.05))), maple}}));
  // Gutters: half-cylinder troughs along the lane, seen from inside (normals towards the axis).
  MeshData gutters;
  for (double side : {-1.0, 1.0}) {
    const double xc = side * (half + r_gutter);
    gutters.append(surface(16, static_cast<int>(std::round(lane_length / 0.1)), [&](double u, double v) {
      const double a = kPi * u;
      const Vec3d p{xc - r_gutter * std::cos(a), -r_gutter * std::sin(a), kLaneNear - lane_length * v};
      return SurfacePoint{p, Vec3d{xc - p.x, -p.y, 0}};
    }));
  }
  w.node("gutters", w.mesh("gutters", {{gutters, gutter_grey}}));
  // Capping: the strips between this lane and the next ones, beyond the gutters.
  const double outer = half + kGutterWidth;
  MeshData caps;
  caps.append(grid({-outer - 0.4, 0, kLaneNear}, {0.4, 0, 0}, {0, 0, -lane_length}, 4, static_cast<int>(lane_length / 0.1)));
  caps.append(grid({outer, 0, kLaneNear}, {0.4, 0, 0}, {0, 0, -lane_length}, 4, static_cast<int>(lane_length / 0.1)));
  w.node("capping", w.mesh("capping", {{caps, capping}}));
  // Kickbacks: the side walls along the pin deck, from 1.3 m in front of the head pin to the back.
  const double kick_front = 1.3, kick_back = kPinDeckBack - kPitLength, kick_height = 0.8;
  MeshData kicks;
  kicks.append(grid({-outer, 0, kick_front}, {0, 0, kick_back - kick_front}, {0, kick_height, 0}, 40, 16));  // faces +X
  kicks.append(grid({outer, 0, kick_back}, {0, 0, kick_front - kick_back}, {0, kick_height, 0}, 40, 16));   // faces -X
  w.node("kickbacks", w.mesh("kickbacks", {{kicks, kickback}}));
  // Pit (a sunken floor behind the deck) and the masking wall behind it.
  MeshData pit;
  pit.append(grid({-outer, -kPitDepth, kPinDeckBack}, {2 * outer, 0, 0}, {0, 0, -kPitLength}, 24, 12));
  pit.append(grid({-outer, -kPitDepth, kPinDeckBack}, {0, kPitDepth, 0}, {2 * outer, 0, 0}, 24, 4));  // deck edge
  pit.append(grid({-outer, -kPitDepth, kick_back}, {2 * outer, 0, 0}, {0, kBackWallHeight + kPitDepth, 0}, 24, 24));
  w.node("pit", w.mesh("pit", {{pit, dark}}));

  // One pin mesh, instanced ten times: white body with the two red neck stripes.
  const double stripes[4] = {9.0, 9.45, 10.55, 11.0};  // inches: stripe 1 from 9.0 to 9.45, stripe 2 from 10.55 to 11.0
  const double cuts[6] = {0, stripes[0], stripes[1], stripes[2], stripes[3], kPinHeightIn};
  std::vector<std::pair<MeshData, int>> pin_parts;
  MeshData white;
  for (int k = 0; k < 5; ++k) {
    const int rings = std::max(2, static_cast<int>(std::round((cuts[k + 1] - cuts[k]) * 4)));
    MeshData part = lathe(pin_profile, cuts[k], cuts[k + 1], rings, 32);
    if (k % 2 == 0) white.append(part);
    else pin_parts.push_back({part, pin_red});
  }
  pin_parts.insert(pin_parts.begin(), {white, pin_white});
  const int pin = w.mesh("pin", pin_parts);
  // Pins 1..10: row k (0 = head pin) at z = -k * spacing * sin 60 deg, spread across x.
  int number = 1;
  for (int row = 0; row < 4; ++row)
    for (int i = 0; i <= row; ++i, ++number)
      w.node("pin " + std::to_string(number), pin,
             {(i - row / 2.0) * kPinSpacing, 0, -row * kPinSpacing * std::sqrt(3.0) / 2});

  // The ball, rolling towards the pocket.
  w.node("ball", w.mesh("ball", {{sphere({0, 0, 0}, kBallRadius, 24, 48), ball_blue}}), {0.12, kBallRadius, 2.2});

  // Looking down the lane from the approach, a little above head height, as in the figures.
  w.camera({0.0, 1.05, 4.6}, {0.0, 0.1, -0.35}, 0.40, 4.0 / 3.0);
  return w.write(dir + "/bowling.glb");
}

void write_bowling_lights(const std::string& dir) {
  // Figure 3: spotlights above the pins and the ball, hard cones (a narrow penumbra), so the
  // cutoff of each cone shows on the lane.
  LightsJson spot;
  spot.spot("pins", {0, 3.2, 0.6}, {0, 0, -0.45}, 0.30, 0.34, 3.6, kWarmWhite);
  spot.spot("ball", {0.6, 3.0, 3.4}, {0.1, 0, 2.2}, 0.22, 0.26, 3.2, kWarmWhite);
  spot.spot("lane", {-0.4, 3.0, 4.6}, {0, 0, 3.9}, 0.30, 0.34, 2.6, kWarmWhite);
  spot.write(dir + "/bowling-spot.json");
  // Figure 4: fluorescent tubes across the lane under a low ceiling, one over the pin deck.
  LightsJson linear;
  const double tube_half = 0.7, tube_y = 2.6;
  const double tube_z[4] = {-0.3, 1.3, 2.9, 4.5};
  for (int k = 0; k < 4; ++k)
    linear.linear("tube " + std::to_string(k + 1), {-tube_half, tube_y, tube_z[k]}, {tube_half, tube_y, tube_z[k]},
                  k == 0 ? 2.0 : 1.5, kCoolWhite);
  linear.write(dir + "/bowling-linear.json");
  // Figure 7: 1.6 m square ceiling panels directly overhead, emitting downwards (edge vectors
  // u = +X, v = +Z: cross(u, v) = -Y). Large and low, so that a small intensity lights the lane:
  // the paper's area specular (eq. 11-12) does not shrink with the light's solid angle.
  LightsJson area;
  const double panel_z[3] = {-0.2, 1.8, 3.8};
  for (int k = 0; k < 3; ++k)
    area.panel("panel " + std::to_string(k + 1), {0, 2.6, panel_z[k]}, {1.6, 0, 0}, {0, 0, 1.6}, 3.2, kCoolWhite);
  area.write(dir + "/bowling-area.json");
}

// ---------------------------------------------------------------------------------------------
// Figure 9: a studio. A room 6 m wide, 5 m deep, 3 m high, open towards the camera, with a table
// carrying a vase, a sphere and a torus on the floor, and a stack of boxes.

constexpr double kRoomHalfWidth = 3.0, kRoomBack = -3.0, kRoomFront = 2.0, kRoomHeight = 3.0;

bool write_studio(const std::string& dir) {
  GltfSceneWriter w("vlit generate_paper_scenes (Picott 1992 fig. 9)");
  const auto [floor_m, wall_m, wood, vase_m, sphere_m, torus_m, box_m, box2_m] =
      w.materials({{"floor", {0.55, 0.5, 0.45}, 0.5, 0},
                   {"walls", {0.6, 0.6, 0.58}, 0.9, 0},
                   {"table", {0.45, 0.26, 0.13}, 0.4, 0},
                   {"vase", {0.1, 0.45, 0.5}, 0.15, 0},
                   {"sphere", {0.8, 0.2, 0.15}, 0.25, 0},
                   {"torus", {0.85, 0.65, 0.2}, 0.3, 1},
                   {"boxes", {0.3, 0.45, 0.75}, 0.6, 0},
                   {"small box", {0.85, 0.82, 0.7}, 0.6, 0}});

  const double width = 2 * kRoomHalfWidth, depth = kRoomFront - kRoomBack;
  w.node("floor", w.mesh("floor", {{grid({-kRoomHalfWidth, 0, kRoomFront}, {width, 0, 0}, {0, 0, -depth}, 96, 80), floor_m}}));
  MeshData walls;
  walls.append(grid({-kRoomHalfWidth, 0, kRoomBack}, {width, 0, 0}, {0, kRoomHeight, 0}, 96, 48));            // back
  walls.append(grid({-kRoomHalfWidth, 0, kRoomFront}, {0, 0, -depth}, {0, kRoomHeight, 0}, 80, 48));         // left
  walls.append(grid({kRoomHalfWidth, 0, kRoomBack}, {0, 0, depth}, {0, kRoomHeight, 0}, 80, 48));            // right
  w.node("walls", w.mesh("walls", {{walls, wall_m}}));

  // Table: a top 1.4 x 0.8 m at 0.75 m, four square legs.
  const Vec3d table{-0.6, 0, -0.8};
  const double top_y = 0.75, top_t = 0.05, leg = 0.06;
  MeshData t = box(table + Vec3d{-0.7, top_y - top_t, -0.4}, table + Vec3d{0.7, top_y, 0.4}, 20);
  for (double sx : {-1.0, 1.0})
    for (double sz : {-1.0, 1.0}) {
      const Vec3d c = table + Vec3d{sx * 0.62, 0, sz * 0.32};
      t.append(box(c + Vec3d{-leg / 2, 0, -leg / 2}, c + Vec3d{leg / 2, top_y - top_t, leg / 2}, 20));
    }
  w.node("table", w.mesh("table", {{t, wood}}));

  // Vase on the table: a lathed profile, r(s) a smooth sum of a belly bump and a flared lip.
  const Profile vase_profile = [](double s) {
    const double belly = 0.11 * std::exp(-std::pow((s - 0.35) / 0.25, 2));
    const double lip = 0.035 * std::exp(-std::pow((s - 1.0) / 0.12, 2));
    return ProfilePoint{0.05 + belly + lip, 0.45 * s};
  };
  MeshData vase = lathe(vase_profile, 0, 1, 48, 48);
  for (Vec3d& p : vase.positions) p += table + Vec3d{0.3, top_y, 0.05};
  w.node("vase", w.mesh("vase", {{vase, vase_m}}));

  w.node("sphere", w.mesh("sphere", {{sphere({1.0, 0.45, 0.4}, 0.45, 32, 64), sphere_m}}));
  w.node("torus", w.mesh("torus", {{torus({-0.4, 0.12, 0.9}, 0.3, 0.12, 24, 64), torus_m}}));
  MeshData boxes = box({1.4, 0, -2.2}, {2.2, 0.8, -1.4}, 16);
  w.node("boxes", w.mesh("boxes", {{boxes, box_m}}));
  MeshData small = box({1.55, 0.8, -2.05}, {2.0, 1.25, -1.6}, 16);
  small.append(cylinder({-2.0, 0, -2.2}, 0.25, 1.1, 12, 48));
  small.append(disk({-2.0, 1.1, -2.2}, 0.25, true, 4, 48));
  w.node("stand", w.mesh("stand", {{small, box2_m}}));

  w.camera({2.6, 2.1, 4.6}, {-0.1, 0.55, -0.9}, 0.72, 4.0 / 3.0);
  return w.write(dir + "/studio.glb");
}

void write_studio_lights(const std::string& dir) {
  // 9a: three spots from the ceiling corners onto the table, the sphere and the boxes.
  LightsJson spot;
  spot.spot("key", {1.8, 2.9, 1.8}, {-0.4, 0.75, -0.8}, 0.35, 0.45, 3.2, kWarmWhite);
  spot.spot("sphere", {-1.6, 2.9, 1.6}, {1.0, 0.3, 0.4}, 0.3, 0.4, 3.0, kWarmWhite);
  spot.spot("boxes", {0.2, 2.9, -0.6}, {1.8, 0.8, -1.8}, 0.35, 0.45, 2.4, kCoolWhite);
  spot.write(dir + "/studio-spot.json");
  // 9b: two long tubes under the ceiling, front to back, and one upright tube by the left wall.
  LightsJson linear;
  linear.linear("ceiling left", {-1.2, 2.9, 1.5}, {-1.2, 2.9, -2.5}, 1.4, kCoolWhite);
  linear.linear("ceiling right", {1.2, 2.9, 1.5}, {1.2, 2.9, -2.5}, 1.4, kCoolWhite);
  linear.linear("upright", {-2.7, 0.3, 0.5}, {-2.7, 2.4, 0.5}, 0.6, kWarmWhite);
  linear.write(dir + "/studio-linear.json");
  // 9c: a large ceiling panel (emitting down) and a softbox facing the set from the left
  // (edge vectors u = -Z, v = +Y: cross(u, v) = +X).
  LightsJson area;
  area.panel("ceiling", {0, 2.95, -0.5}, {2.4, 0, 0}, {0, 0, 2.0}, 2.0, kCoolWhite);
  area.panel("softbox", {-2.6, 1.4, 0.6}, {0, 0, -1.0}, {0, 1.2, 0}, 2.0, kWarmWhite);
  area.write(dir + "/studio-area.json");
}

}  // namespace
}  // namespace vlit

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  try {
    std::filesystem::create_directories(dir);
    if (!vlit::write_bowling(dir) || !vlit::write_studio(dir)) return 1;
    vlit::write_bowling_lights(dir);
    vlit::write_studio_lights(dir);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
