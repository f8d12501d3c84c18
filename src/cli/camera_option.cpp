#include "cli/camera_option.h"

#include <charconv>

#include "cli/usage_error.h"

namespace vlit::cli {
namespace {

// "0 \"Front\", 2 (no name)" or "none".
std::string list_cameras(const Scene& scene) {
  if (scene.cameras.empty()) return "it has none";
  std::string out = "it has ";
  for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
    const SceneCamera& c = scene.cameras[i];
    if (i > 0) out += ", ";
    out += std::to_string(c.index) + (c.name.empty() ? " (no name)" : " \"" + c.name + "\"");
  }
  return out;
}

}  // namespace

std::optional<SceneCamera> choose_camera(const Scene& scene, const std::string& choice, const std::string& input) {
  if (choice.empty()) return scene.cameras.empty() ? std::nullopt : std::optional(scene.cameras.front());
  if (choice == "auto") return std::nullopt;
  int index = -1;
  const char* end = choice.data() + choice.size();
  const auto [ptr, ec] = std::from_chars(choice.data(), end, index);
  const bool is_index = ec == std::errc() && ptr == end;
  for (const SceneCamera& c : scene.cameras)
    if (is_index ? c.index == index : c.name == choice) return c;
  throw UsageError(input + ": --camera " + choice + ": no " + (is_index ? "camera of that index" : "camera of that name") +
                   " in the scene (" + list_cameras(scene) + "; auto frames the scene)");
}

}  // namespace vlit::cli
