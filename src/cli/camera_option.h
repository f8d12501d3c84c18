// render --camera INDEX|NAME|auto: which camera of the scene an image is drawn from.
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"

namespace vlit::cli {

// `choice` empty: the scene's first camera, or nothing (frame the scene) when it has none.
// "auto": nothing, whatever the file has (the 3/4 view framing the scene).
// A number: the glTF camera cameras[INDEX]; anything else: the camera of that name (the camera's
// own name, else its node's). Throws UsageError naming `input` and every camera the scene has
// when none matches.
std::optional<SceneCamera> choose_camera(const Scene& scene, const std::string& choice, const std::string& input);

}  // namespace vlit::cli
