// Frames per second of vlit's rasterizer against Mesa's llvmpipe on the same vertex-coloured mesh,
// Gouraud only, one sample per pixel, in one process (docs/rasterizer.md has the table):
//   large: a wavy terrain of ~1M triangles at 1920 x 1080
//   small: the same terrain with 2 048 triangles at 3840 x 2160 (fill-bound)
// The meshes are made here (no files). Both renderers get the same camera matrix, the same
// thread count (OpenMP threads for vlit, LP_NUM_THREADS for llvmpipe, set by this program) and
// run interleaved frame by frame, so a load change on the machine hits both; the table reports
// the median frame time of each. A frame of vlit is one raster::render call (transform, clip,
// setup, scan, depth test, Gouraud, resolve into a float RGB image) with a RenderWorkspace and an
// Image kept between frames, as llvmpipe keeps its bins and framebuffer; the first frame (fresh
// buffers, what `vlit render` pays once) is reported separately. A frame of llvmpipe is
// clear + draw + glFinish into an RGBA8 framebuffer. After timing, the two images are compared
// (8-bit linear values) to show they drew the same picture. The CPU time of each frame (all
// threads of the process) is reported too: on a shared machine it depends less on other load.
//
// Usage: raster_vs_llvmpipe [--threads N] [--frames N] [--quick] [--png-dir DIR] [--only large|small] [--vlit-only]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "llvmpipe_renderer.h"
#include "raster/raster.h"

using namespace vlit;

namespace {

struct Case {
  const char* name;
  int grid;  // vertices per side; triangles = 2 (grid - 1)^2
  int width, height;
};

// A (grid x grid) terrain over [-1, 1]^2 with smooth hills and smoothly varying colours.
raster::DrawMesh make_terrain(int grid) {
  raster::DrawMesh mesh;
  mesh.positions.reserve(size_t(grid) * grid);
  mesh.colors.reserve(size_t(grid) * grid);
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const float u = float(i) / float(grid - 1), v = float(j) / float(grid - 1);
      const float x = 2 * u - 1, z = 2 * v - 1;
      const float y = 0.08f * std::sin(7 * x + 1.3f) * std::cos(5 * z) + 0.05f * std::sin(13 * x * z);
      mesh.positions.push_back({x, y, z});
      mesh.colors.push_back({0.2f + 0.8f * u, 0.3f + 0.5f * (0.5f + 6 * y), 0.2f + 0.8f * v});
    }
  for (uint32_t j = 0; j + 1 < uint32_t(grid); ++j)
    for (uint32_t i = 0; i + 1 < uint32_t(grid); ++i) {
      const uint32_t a = j * grid + i, b = a + 1, c = a + grid + 1, d = a + grid;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, a, d, c});  // counter-clockwise from above
    }
  return mesh;
}

raster::Camera bench_camera() {
  raster::Camera camera;
  camera.world_from_camera = look_at(Vec3d{0, 1.5, 1.25}, Vec3d{0, 0, 0.05}, Vec3d{0, 1, 0});
  camera.yfov = 0.75;
  camera.znear = 0.1;
  camera.zfar = 10;
  return camera;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// CPU time of the whole process (all threads, vlit's and llvmpipe's): on a shared machine the
// wall time of a frame depends on the other load, its CPU time much less.
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int threads = omp_get_max_threads(), frames = 15;
  bool quick = false, vlit_only = false;
  std::string png_dir, only;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--threads" && i + 1 < argc) threads = std::atoi(argv[++i]);
    else if (a == "--frames" && i + 1 < argc) frames = std::atoi(argv[++i]);
    else if (a == "--quick") quick = true;
    else if (a == "--vlit-only") vlit_only = true;
    else if (a == "--png-dir" && i + 1 < argc) png_dir = argv[++i];
    else if (a == "--only" && i + 1 < argc) only = argv[++i];
    else {
      std::fprintf(stderr, "usage: raster_vs_llvmpipe [--threads N] [--frames N] [--quick] [--png-dir DIR] [--only large|small] [--vlit-only]\n");
      return 2;
    }
  }
  if (threads < 1 || frames < 1) return 2;
  omp_set_num_threads(threads);
  setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);  // before the driver loads
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  if (quick) frames = 2;

  const std::vector<Case> cases = quick ? std::vector<Case>{{"large", 101, 192, 108}, {"small", 33, 384, 216}}
                                        : std::vector<Case>{{"large", 708, 1920, 1080}, {"small", 33, 3840, 2160}};
  std::printf("threads %d (OpenMP for vlit, LP_NUM_THREADS=%d for llvmpipe), %d timed frames each, median\n", threads,
              threads, frames);
  std::printf("| case | triangles | image | vlit first frame ms | vlit ms | vlit fps | llvmpipe ms | llvmpipe fps | vlit / llvmpipe speed | vlit CPU ms | llvmpipe CPU ms | pixels off by > 2/255 |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  bool baseline_missing = false;
  int renderer_printed = 0;
  for (const Case& c : cases) {
    if (!only.empty() && only != c.name) continue;
    const raster::DrawMesh mesh = make_terrain(c.grid);
    const raster::Camera camera = bench_camera();
    raster::RenderOptions options;
    options.width = c.width;
    options.height = c.height;
    options.samples = 1;
    options.background = {0.05f, 0.05f, 0.08f};
    const std::vector<raster::DrawMesh> meshes{mesh};

    std::string error;
    std::unique_ptr<vlit::bench::LlvmpipeRenderer> gl;
    if (!vlit_only) gl = vlit::bench::LlvmpipeRenderer::create(c.width, c.height, &error);
    else error = "--vlit-only";
    if (gl) {
      std::vector<float> positions, colors;
      for (const auto& p : mesh.positions) positions.insert(positions.end(), {p.x, p.y, p.z});
      for (const auto& col : mesh.colors) colors.insert(colors.end(), {col.x, col.y, col.z});
      gl->upload(positions, colors, mesh.indices);
      if (!renderer_printed++) std::printf("baseline renderer: %s\n", gl->renderer().c_str());
    } else if (!baseline_missing) {
      std::printf("llvmpipe unavailable (%s): vlit timed alone\n", error.c_str());
      baseline_missing = true;
    }
    const Mat4d m = *raster::clip_from_world(camera, double(c.width) / c.height);
    std::array<float, 16> column_major{};
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) column_major[col * 4 + row] = float(m.m[row][col]);
    const std::array<float, 3> background{options.background.x, options.background.y, options.background.z};

    // Warm-up: the first frame allocates (and page-faults) the workspace and the image.
    raster::RenderWorkspace workspace;
    raster::Image image;
    auto t0 = std::chrono::steady_clock::now();
    raster::render(meshes, camera, options, workspace, image);
    const double first_frame = seconds_since(t0);
    if (gl) gl->draw(column_major, background);
    std::vector<double> ours, theirs, ours_cpu, theirs_cpu;
    for (int f = 0; f < frames; ++f) {
      auto t = std::chrono::steady_clock::now();
      double cpu = process_cpu_seconds();
      raster::render(meshes, camera, options, workspace, image);
      ours.push_back(seconds_since(t));
      ours_cpu.push_back(process_cpu_seconds() - cpu);
      if (gl) {
        t = std::chrono::steady_clock::now();
        cpu = process_cpu_seconds();
        gl->draw(column_major, background);
        theirs.push_back(seconds_since(t));
        theirs_cpu.push_back(process_cpu_seconds() - cpu);
      }
    }
    // Sanity: the same picture (8-bit linear, no sRGB on either side).
    std::string differing = "-";
    std::vector<uint8_t> ours8(image.rgb.size());
    for (size_t i = 0; i < ours8.size(); ++i) ours8[i] = uint8_t(std::lround(std::clamp(image.rgb[i], 0.0f, 1.0f) * 255.0f));
    if (gl) {
      const std::vector<uint8_t> theirs8 = gl->read_rgb8();
      size_t off = 0;
      for (size_t p = 0; p < theirs8.size(); p += 3) {
        bool bad = false;
        for (int k = 0; k < 3; ++k) bad = bad || std::abs(int(ours8[p + k]) - int(theirs8[p + k])) > 2;
        off += bad;
      }
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.3f%%", 100.0 * double(off) / double(size_t(c.width) * c.height));
      differing = buf;
      if (!png_dir.empty()) raster::write_png(png_dir + "/" + c.name + "-llvmpipe.png", c.width, c.height, theirs8, nullptr);
    }
    if (!png_dir.empty()) raster::write_png(png_dir + "/" + c.name + "-vlit.png", c.width, c.height, ours8, nullptr);
    const double ours_s = median(ours), theirs_s = median(theirs);
    if (gl)
      std::printf("| %s | %zu | %dx%d | %.1f | %.1f | %.2f | %.1f | %.2f | %.2f | %.1f | %.1f | %s |\n", c.name,
                  mesh.indices.size() / 3, c.width, c.height, 1e3 * first_frame, 1e3 * ours_s, 1 / ours_s, 1e3 * theirs_s,
                  1 / theirs_s, theirs_s / ours_s, 1e3 * median(ours_cpu), 1e3 * median(theirs_cpu), differing.c_str());
    else
      std::printf("| %s | %zu | %dx%d | %.1f | %.1f | %.2f | - | - | - | %.1f | - | - |\n", c.name, mesh.indices.size() / 3,
                  c.width, c.height, 1e3 * first_frame, 1e3 * ours_s, 1 / ours_s, 1e3 * median(ours_cpu));
  }
  return 0;
}
