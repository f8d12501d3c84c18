// Shared by the files of the library facade (include/vlit/vlit.h): the conversions between the
// public types and the internal ones, the translation of internal errors, and the per-call
// thread count. Nothing here is installed.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <vlit/vlit.h>

#include "core/input_error.h"
#include "gltf/gltf_scene.h"
#include "scene/light_source.h"
#include "scene/scene.h"
#include "shading/prepared_light.h"

namespace vlit {

struct Lights::Impl {
  std::vector<LightSource> sources;  // validated, in the order they were added
};

namespace api {

inline Vec3d to_vec3d(const Vector3& v) { return {v[0], v[1], v[2]}; }
inline Vector3 to_vector3(const Vec3d& v) { return {v.x, v.y, v.z}; }

// Runs `body`, turning internal errors into vlit::Error: an InputError keeps its file, place and
// problem; any other std::exception (but bad_alloc) is attributed to `input`.
template <class Body>
auto translate_errors(const std::string& input, Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const Error&) {
    throw;
  } catch (const InputError& e) {
    throw Error(e.file(), e.problem(), e.where());
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(input, e.what());
  }
}

// Sets the OpenMP thread count of the calling thread for the lifetime of the object (0 = leave
// it), and restores it after. omp_set_num_threads changes only the calling thread's setting.
class ThreadCount {
 public:
  explicit ThreadCount(int threads);
  ~ThreadCount();
  ThreadCount(const ThreadCount&) = delete;
  ThreadCount& operator=(const ThreadCount&) = delete;

 private:
  int saved_ = 0;
  bool changed_ = false;
};

// Throws Error(input, ...) for settings out of range (what CLI11 checks on the command line).
void check_settings(const Settings& settings, const std::string& input);
ShadeOptions shade_options(const Settings& settings);
SceneLimits scene_limits(const Settings& settings);
bool cancelled(const Settings& settings);

// A Scene of world-space meshes, one primitive and one material each; throws Error naming the mesh.
Scene scene_of_meshes(const std::vector<Mesh>& meshes);

}  // namespace api
}  // namespace vlit
