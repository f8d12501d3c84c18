// Reading a glTF extension object (a tinygltf::Value, which the loader keeps as parsed JSON) with
// checks, so the light readers never see malformed data: every problem is an InputError naming
// the file and the JSON path of the bad value, e.g.
//   "lamp.gltf: extensions.EXT_lights_area.lights[0].size: expected a number > 0".
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/vec3.h"

namespace vlit {

class ExtensionObject {
 public:
  // Throws unless `value` is a JSON object.
  ExtensionObject(const tinygltf::Value& value, std::string file, std::string path);

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

  bool has(const std::string& key);
  // A finite number; `fallback` when absent, an error when absent without one.
  double number(const std::string& key, std::optional<double> fallback = std::nullopt);
  Vec3d vec3(const std::string& key, std::optional<Vec3d> fallback = std::nullopt);
  std::string string(const std::string& key, std::optional<std::string> fallback = std::nullopt);
  // A non-negative integer (a glTF index).
  int index(const std::string& key);
  // A nested object; an empty object when absent.
  ExtensionObject object(const std::string& key);
  // A JSON array of objects (e.g. a root "lights" array).
  std::vector<ExtensionObject> objects(const std::string& key);

  // Properties not read so far, besides the glTF-wide "name", "extensions" and "extras".
  std::vector<std::string> unread_keys() const;
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }

 private:
  std::string key_path(const std::string& key) const { return path_ + "." + key; }
  const tinygltf::Value* value_;
  std::string file_, path_;
  std::set<std::string> read_;
};

}  // namespace vlit
