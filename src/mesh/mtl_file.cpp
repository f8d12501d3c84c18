#include "mesh/mtl_file.h"

#include <algorithm>

#include "core/input_error.h"
#include "io/read_file.h"
#include "mesh/wavefront_statements.h"

namespace vlit {
namespace {

// `K? r [g b]` -> RGB; the spectral and xyz forms -> nullopt (with a warning).
std::optional<Vec3d> read_colour(const WavefrontStatement& s, const std::string& path, std::vector<std::string>& warnings) {
  if (!s.arguments.empty() && (s.arguments[0] == "spectral" || s.arguments[0] == "xyz")) {
    warnings.push_back(path + ": " + wavefront_line(s.line) + ": " + s.keyword + " " + s.arguments[0] +
                       " is not supported; statement ignored");
    return std::nullopt;
  }
  if (s.arguments.size() != 1 && s.arguments.size() != 3)
    throw InputError(path, s.keyword + " needs 1 or 3 numbers (r [g b]), got " + std::to_string(s.arguments.size()),
                     wavefront_line(s.line));
  double rgb[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string& token = s.arguments[s.arguments.size() == 1 ? 0 : i];
    rgb[i] = parse_wavefront_number(token, s.keyword, path, s.line);
    if (rgb[i] < 0) throw InputError(path, s.keyword + ": " + token + " is negative", wavefront_line(s.line));
  }
  return Vec3d{rgb[0], rgb[1], rgb[2]};
}

}  // namespace

std::vector<MtlMaterial> read_mtl_file(const std::string& path, std::vector<std::string>& warnings) {
  const std::string text = read_text_file(path);
  std::vector<MtlMaterial> materials;
  for_each_wavefront_statement(text, [&](const WavefrontStatement& s) {
    if (s.keyword == "newmtl") {
      if (s.rest.empty()) throw InputError(path, "newmtl needs a name", wavefront_line(s.line));
      materials.push_back(MtlMaterial{s.rest, {}, {}, {}, {}});
      return;
    }
    const bool read = s.keyword == "Kd" || s.keyword == "Ks" || s.keyword == "Ke" || s.keyword == "Ns";
    if (!read) return;  // every other statement is ignored (the header's list)
    if (materials.empty()) throw InputError(path, s.keyword + " before the first newmtl", wavefront_line(s.line));
    MtlMaterial& m = materials.back();
    if (s.keyword == "Ns") {
      if (s.arguments.size() != 1)
        throw InputError(path, "Ns needs one number, got " + std::to_string(s.arguments.size()), wavefront_line(s.line));
      const double ns = parse_wavefront_number(s.arguments[0], "Ns", path, s.line);
      if (ns < 0) throw InputError(path, "Ns: " + s.arguments[0] + " is negative", wavefront_line(s.line));
      m.ns = ns;
      return;
    }
    const std::optional<Vec3d> colour = read_colour(s, path, warnings);
    if (!colour) return;
    if (s.keyword == "Kd") {
      const Vec3d clamped{std::min(colour->x, 1.0), std::min(colour->y, 1.0), std::min(colour->z, 1.0)};
      if (!(clamped == *colour))
        warnings.push_back(path + ": " + wavefront_line(s.line) + ": Kd above 1 clamped to 1 (a base colour is at most 1)");
      m.kd = clamped;
    } else if (s.keyword == "Ks") {
      m.ks = colour;
    } else {
      m.ke = colour;
    }
  });
  return materials;
}

Material material_from_mtl(const MtlMaterial& mtl) {
  Material m;
  m.name = mtl.name;
  m.base_color = mtl.kd.value_or(Vec3d{0.8, 0.8, 0.8});
  m.metallic = 0;
  m.roughness = mtl.ns ? roughness_for_shininess(*mtl.ns) : 0.5;
  m.emissive_factor = mtl.ke.value_or(Vec3d{0, 0, 0});
  m.emissive_strength = 1;
  m.double_sided = false;
  return m;
}

}  // namespace vlit
