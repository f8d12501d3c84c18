// Accuracy report: error against run time, and stability on stiff and extreme cases, for every
// method of every extended light model (linear diffuse and specular, area diffuse and specular,
// disk), in double and in float; plus one end-to-end bake of a real asset.
//
//   scripts/accuracy-report.sh [--quick]       (builds, runs this program, draws the plots)
//   accuracy_report [--quick] --out-dir DIR [--asset FILE] [--template docs/accuracy.md.in]
//
// Runs the per-model reports (bench/accuracy/*_report.cpp), then writes DIR/tables/*.md (each
// section's tables), DIR/data/*.dat and DIR/data/*.gp (gnuplot scripts that draw
// DIR/images/accuracy/*.png when run from DIR) and, with --template, DIR/accuracy.md: the
// template's prose with this run's tables and numbers filled in by name (fill_template.h; the
// names: report_values.h and below). Exit status 1 if any method returned NaN or Inf.
//
// Errors are measured against independent long-double Boost.Math references in a different
// parametrisation (reference/linear_reference.h, area_reference.h, disk_reference.h). Case inputs
// are rounded to float first, so the same reference serves the double and the float evaluation.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "accuracy/fill_template.h"
#include "accuracy/report_format.h"
#include "accuracy/report_values.h"
#include "accuracy/reports.h"
#include "accuracy_blender.h"
#include "bake/vertex_color_bake.h"
#include "io/atomic_write.h"
#include "load/load_scene.h"
#include "bake/light_vertices.h"
#include "shading/prepared_light.h"

namespace vlit::bench::accuracy {
namespace {

std::string cpu_name() {
  std::ifstream f("/proc/cpuinfo");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

std::string printed(const char* format, double x) {
  char b[64];
  std::snprintf(b, sizeof b, format, x);
  return b;
}

std::string method_name(SpecularMethod m) {
  switch (m) {
    case SpecularMethod::kPeak: return "peak";
    case SpecularMethod::kNeighborhood: return "neighborhood";
    case SpecularMethod::kExact: return "exact";
    default: return "none";
  }
}

// The defaults as the code sets them (not typed in the document): the library's option structs,
// and the rows of the tables that measure them.
void publish_defaults(Values& v) {
  const ShadeOptions shade{};
  const BakeOptions bake{};
  const std::string qtol = tol_key(shade.linear.quadrature_tolerance);
  const std::string etol = tol_key(shade.specular.exact_tolerance);
  const std::string k = std::to_string(shade.specular.neighborhood_samples);
  v["default:quadrature-tolerance"] = printed("%g", shade.linear.quadrature_tolerance);
  v["default:exact-tolerance"] = printed("%g", shade.specular.exact_tolerance);
  v["default:neighborhood-samples"] = k;
  v["default:specular-method"] = method_name(shade.specular.method);
  v["default:color-format"] = bake.format == ColorFormat::kUnorm16 ? "unorm16" : bake.format == ColorFormat::kUnorm8 ? "unorm8" : "float";
  v["default:float-batch"] = LightingRequest{}.float_batch ? "true" : "false";
  publish_alias(v, "linear-diffuse", "adaptive-" + qtol + "-n1.5", "default:linear-quadrature-n1.5");
  publish_alias(v, "linear-diffuse", "adaptive-" + qtol + "-n2", "default:linear-quadrature-n2");
  publish_alias(v, "linear-specular", "exact-" + etol, "default:linear-exact");
  publish_alias(v, "area-specular", "exact-" + etol, "default:area-exact");
  publish_alias(v, "linear-specular", "neighbourhood-" + k, "default:linear-neighbourhood");
  publish_alias(v, "area-specular", "neighbourhood-" + k, "default:area-neighbourhood");
  publish_alias(v, "disk-specular", "exact-" + etol, "default:disk-exact");
}

void publish_linear_extras(Values& v, const LinearSections& lin) {
  v["linear-specular:peak-vs-max:d.med"] = fmt(lin.peak_vs_max.med);
  v["linear-specular:peak-vs-max:d.p99"] = fmt(lin.peak_vs_max.p99);
  v["linear-specular:peak-vs-max:d.max"] = fmt(lin.peak_vs_max.max);
  v["linear-specular:peak-vs-max:f.max"] = fmt(lin.peak_vs_max_float.max);
  if (lin.ratio_count > 0) {
    v["linear-specular:ratio:count"] = std::to_string(lin.ratio_count);
    v["linear-specular:ratio:min"] = fmt(lin.ratio_min);
    v["linear-specular:ratio:med"] = fmt(lin.ratio_med);
    v["linear-specular:ratio:max"] = fmt(lin.ratio_max);
  }
}

void publish_end_to_end(Values& v, const Options& o, const EndToEnd& e) {
  v["asset"] = o.asset;
  if (!e.done) return;
  v["end-to-end"] = "yes";
  v["end-to-end:asset"] = e.asset_name;
  v["end-to-end:vertices"] = std::to_string(e.vertices);
  v["end-to-end:triangles"] = std::to_string(e.triangles);
  v["end-to-end:table"] = e.table;
  v["end-to-end:light-top"] = fmt(e.light_top);
  v["end-to-end:batch:max-rel"] = fmt(e.batch.max_rel);
  v["end-to-end:batch:ms"] = fmt_ns(e.batch.seconds * 1e3);
  v["end-to-end:double:max-rel"] = fmt(e.scalar_double.max_rel);
  v["end-to-end:double:ms"] = fmt_ns(e.scalar_double.seconds * 1e3);
  v["unorm16-step"] = fmt(0.5 / 65535);
  for (std::size_t i = 0; i < e.formats.size(); ++i) {
    const auto& f = e.formats[i];
    const std::string p = "format" + std::to_string(i) + ":";
    v[p + "max-quantization"] = fmt(f.max_quantization);
    v[p + "clipped"] = std::to_string(f.clipped);
    v[p + "bytes"] = std::to_string(f.bytes);
    v[p + "encode-us"] = fmt_ns(f.seconds * 1e6);
  }
  if (!e.formats.empty()) v["formats"] = "yes";
  if (e.formats.size() == 3) v["three-formats"] = "yes";
  const CyclesComparison& c = e.cycles;
  if (!c.available) {
    if (c.why_not.empty()) v["cycles:not-run"] = "yes";
    else v["cycles:why-not"] = c.why_not;
    return;
  }
  v["cycles"] = "yes";
  v["cycles:asset"] = c.asset_name;
  v["cycles:vertices"] = std::to_string(c.vertices);
  v["cycles:triangles"] = std::to_string(c.triangles);
  v["cycles:lights-file"] = c.lights_name;
  v["cycles:blender-version"] = c.blender_version;
  v["cycles:runs"] = std::to_string(c.runs_counted);
  v["cycles:unmatched"] = std::to_string(c.unmatched);
  v["cycles:import-s"] = fmt(c.import_seconds);
  v["cycles:table"] = c.table;
  v["cycles:lights"] = std::to_string(c.cycles_lights);
  v["cycles:tube-points"] = std::to_string(c.tube_points);
  v["cycles:best-samples"] = std::to_string(c.best_samples);
  v["cycles:best-error"] = fmt(c.best_error);
  v["cycles:best-s"] = printed("%.3g", c.best_seconds);
  v["cycles:vlit-s"] = printed("%.3g", c.vlit_seconds);
  if (c.vlit_error == 0) v["cycles:vlit-identical"] = "yes";
  else v["cycles:vlit-error"] = fmt(c.vlit_error);
  v["cycles:ratio"] = printed("%.0f", c.ratio_at_best);
  v["cycles:slope-med"] = printed("%.2f", c.slope_med);
  v["cycles:slope-max"] = printed("%.2f", c.slope_max);
  v["cycles:samples-needed"] = printed("%.2g", c.samples_needed);
  v["cycles:seconds-needed"] = printed("%.2g", c.seconds_needed);
  v["cycles:ratio-needed"] = printed("%.0e", c.seconds_needed / c.vlit_seconds);
  v["cycles:chain-error"] = fmt(c.chain_error);
  v["cycles:calibration"] = c.calibration;
  v["cycles:cli-bake"] = c.cli_bake;
}

std::string read_text(const fs::path& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path.string() + ": cannot read");
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace
}  // namespace vlit::bench::accuracy

int main(int argc, char** argv) {
  using namespace vlit::bench::accuracy;
  namespace bench = vlit::bench;
  Options o;
  std::string write_lights;
  fs::path template_path;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") o.quick = true;
    else if (a == "--out-dir" && i + 1 < argc) o.out_dir = argv[++i];
    else if (a == "--asset" && i + 1 < argc) o.asset = argv[++i];
    else if (a == "--blender" && i + 1 < argc) o.blender_dir = argv[++i];
    else if (a == "--template" && i + 1 < argc) template_path = argv[++i];
    else if (a == "--write-blender-lights" && i + 1 < argc) write_lights = argv[++i];
    else {
      std::fprintf(stderr,
                   "usage: accuracy_report [--quick] --out-dir DIR [--asset FILE] [--blender CYCLES_DIR] [--template FILE]\n"
                   "       accuracy_report --asset FILE --write-blender-lights LIGHTS.json\n");
      return 2;
    }
  }
  // An asset named but absent is an error (the ctest entry must not pass without its input);
  // no --asset at all runs the kernel tables only.
  if (!o.asset.empty() && !fs::is_regular_file(o.asset)) {
    std::fprintf(stderr, "accuracy_report: %s: no such file\n", o.asset.c_str());
    return 2;
  }
  if (!write_lights.empty()) {  // the comparison lights for bench/blender_bake.py, then stop
    try {
      const vlit::LoadedScene loaded = vlit::load_scene(o.asset, "", {vlit::SceneLimits{}, false});
      const std::string text = bench::lights_json(bench::blender_comparison_lights(loaded.scene));
      std::ofstream f(write_lights);
      f << text;
      if (!f) throw std::runtime_error(write_lights + ": cannot write");
    } catch (const std::exception& e) {
      std::fprintf(stderr, "accuracy_report: %s\n", e.what());
      return 2;
    }
    return 0;
  }
  if (o.out_dir.empty()) {
    std::fprintf(stderr, "accuracy_report: --out-dir is required\n");
    return 2;
  }
  // The template is read before the hour of measuring, so that a wrong path fails at once.
  std::string template_text;
  try {
    if (!template_path.empty()) template_text = read_text(template_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accuracy_report: %s\n", e.what());
    return 2;
  }
  o.reps = o.quick ? 1 : 5;
  fs::create_directories(o.out_dir / "data");
  fs::create_directories(o.out_dir / "images" / "accuracy");
  const auto t_start = std::chrono::steady_clock::now();

  LinearSections lin = linear_report(o);
  AreaSections area = area_report(o);
  DiskSections disk = disk_report(o);
  progress("end to end");
  const EndToEnd e2e = end_to_end(o);
  const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();

  const std::vector<const Section*> sections{&lin.diffuse, &lin.specular, &area.diffuse, &area.specular, &disk.diffuse, &disk.specular};
  int nonfinite = e2e.nonfinite;
  for (const Section* s : sections) nonfinite += s->nonfinite;
  try {
    Values v;
    for (const Section* s : sections) {
      write_plot(o, *s);
      publish_section(v, o, *s);
    }
    publish_defaults(v);
    publish_linear_extras(v, lin);
    publish_end_to_end(v, o, e2e);
    if (o.quick) v["quick"] = "yes";
    if (nonfinite) v["nonfinite"] = "yes";
    if (!o.blender_dir.empty()) v["blender-dir"] = "yes";
    v["cpu"] = cpu_name();
    v["run-seconds"] = std::to_string(int(total_s));
    v["reps"] = std::to_string(o.reps);
    v["linear-count"] = std::to_string(lin.diffuse.ordinary_cases);
    v["area-count"] = std::to_string(area.diffuse.ordinary_cases);
    v["disk-count"] = std::to_string(disk.diffuse.ordinary_cases);
    // Filled completely before anything is written: a template error leaves no half document.
    if (!template_text.empty())
      vlit::write_file_atomically((o.out_dir / "accuracy.md").string(), fill_template(template_text, v, template_path.string()));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accuracy_report: %s\n", e.what());
    return 2;
  }
  return nonfinite ? 1 : 0;
}
