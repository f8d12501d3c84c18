// Accuracy report, end to end against Blender Cycles: the asset lit by the lights Cycles can
// represent (reference/accuracy_blender.h), vlit's lighting stage under four settings against
// Cycles' bakes of bench/blender_bake.py at increasing sample counts, errors per vertex against
// vlit's reference setting. Returns the table and the numbers; the text around them is in
// docs/accuracy.md.in ("Against Blender Cycles").
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "accuracy_blender.h"
#include "bake/light_vertices.h"
#include "load/load_scene.h"
#include "report_format.h"
#include "reports.h"

namespace vlit::bench::accuracy {

CyclesComparison cycles_comparison(const Options& o) {
  CyclesComparison out;
  if (o.blender_dir.empty() || o.asset.empty() || !fs::exists(o.asset)) return out;  // not run
  const fs::path lights_path = o.blender_dir / "lights.json";
  if (!fs::exists(lights_path)) {
    out.why_not = ": no `" + lights_path.string() + "`";
    return out;
  }
  LoadedScene loaded = load_scene(o.asset, lights_path.string(), {SceneLimits{}, false});
  Scene& scene = loaded.scene;
  const CyclesData cy = read_cycles(o.blender_dir, scene);
  if (!cy.available) {
    out.why_not = " (" + cy.why_not + ")";
    return out;
  }
  out.available = true;
  // vlit on the same lights, one thread, diffuse only (what `vlit bake` computes).
  // float_batch: LightingRequest::float_batch (the bake's default); the reference stays in scalar double.
  struct Setting { std::string name; double quad_tol; bool chains; bool float_batch; };
  const std::vector<Setting> settings{{"vlit reference: quadrature 1e-14, scalar double", 1e-14, false, false},
                                      {"vlit default: quadrature 1e-10", 1e-10, false, true},
                                      {"vlit fast: quadrature 1e-6", 1e-6, false, true},
                                      {"vlit on Cycles' scene: each tube as 32 point lights", 1e-10, true, true}};
  omp_set_num_threads(1);
  const std::vector<LightSource> lights = scene.lights;
  std::vector<std::vector<float>> values;
  std::vector<double> seconds;
  out.runs_counted = o.quick ? 1 : 3;
  for (const Setting& st : settings) {
    scene.lights = st.chains ? as_point_chains(lights, kCyclesTubePoints) : lights;
    LightingRequest req;
    req.shade.with_specular = false;
    req.shade.linear.quadrature_tolerance = st.quad_tol;
    req.float_batch = st.float_batch;
    double best = 1e300;
    std::vector<VertexLight> r;
    for (int rep = 0; rep < out.runs_counted; ++rep) {
      const auto t0 = std::chrono::steady_clock::now();
      r = light_scene_vertices(scene, req);
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    values.push_back(diffuse_red(r));
    seconds.push_back(best);
    std::fprintf(stderr, "  cycles comparison %-50s %.4f s\n", st.name.c_str(), best);
  }
  scene.lights = lights;
  const std::vector<float>& ref = values[0];
  out.asset_name = fs::path(o.asset).filename().string();
  out.lights_name = lights_path.filename().string();
  out.blender_version = cy.version;
  out.vertices = scene.vertex_count();
  for (const auto& p : scene.primitives) out.triangles += p.triangles.size() / 3;
  out.unmatched = cy.runs.front().unmatched;
  out.import_seconds = cy.import_seconds;
  std::ostringstream md;
  md << "| method | samples | time (s) | max/top | p99 rel | median rel |\n|---|---|---|---|---|---|\n";
  std::ofstream vdat(o.out_dir / "data" / "end-to-end-vlit-cycles-lights.dat");
  std::ofstream cdat(o.out_dir / "data" / "end-to-end-cycles.dat");
  char t[64];
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const DiffuseError e = diffuse_error(values[i], ref);
    std::snprintf(t, sizeof t, "%.4f", seconds[i]);
    md << "| " << settings[i].name << " | - | " << t << " | " << fmt(e.max_rel_to_max) << " | " << fmt(e.p99_rel)
       << " | " << fmt(e.med_rel) << " |\n";
    if (i > 0)
      vdat << "\"" << (settings[i].chains ? "vlit, point chains" : settings[i].name.substr(5, settings[i].name.find(':') - 5))
           << "\" " << seconds[i] << " " << std::max(e.max_rel_to_max, kEndToEndZero) << "\n";
  }
  std::vector<DiffuseError> cerr;
  for (const CyclesRun& run : cy.runs) {
    const DiffuseError e = diffuse_error(run.value, ref);
    cerr.push_back(e);
    std::snprintf(t, sizeof t, "%.3f", run.seconds);
    md << "| Cycles | " << run.samples << " | " << t << " | " << fmt(e.max_rel_to_max) << " | " << fmt(e.p99_rel) << " | "
       << fmt(e.med_rel) << " |\n";
    cdat << "\"" << run.samples << "\" " << run.seconds << " " << e.max_rel_to_max << "\n";
  }
  out.table = md.str();
  out.cycles_lights = as_point_chains(lights, kCyclesTubePoints).size();
  out.tube_points = kCyclesTubePoints;
  out.chain_error = diffuse_error(values[3], ref).max_rel_to_max;
  // Time ratio. Cycles' error falls as 1/sqrt(samples) (until the point-chain floor); vlit's
  // default is more accurate than every Cycles point, so Cycles' time at its most accurate point
  // over vlit's time is a lower bound of the ratio at equal error; the extrapolation to the error
  // a unorm16 colour can show (1.5e-5) uses the 1/sqrt(N) law from the most accurate point.
  const std::size_t best = cy.runs.size() - 1;
  out.best_samples = cy.runs[best].samples;
  out.best_seconds = cy.runs[best].seconds;
  out.vlit_seconds = seconds[1];
  out.ratio_at_best = cy.runs[best].seconds / seconds[1];
  out.best_error = cerr[best].max_rel_to_max;
  const double target = 1.5e-5;
  out.samples_needed = cy.runs[best].samples * (out.best_error / target) * (out.best_error / target);
  out.seconds_needed = cy.runs[best].seconds * out.samples_needed / cy.runs[best].samples;
  // Exponents of the errors against samples between the two most accurate points: the median
  // checks the Monte Carlo law (-0.5); the max over vertices is dominated by rare outliers and
  // falls irregularly.
  if (cy.runs.size() >= 2) {
    const double r = std::log(double(cy.runs[best].samples) / cy.runs[best - 1].samples);
    out.slope_med = std::log(cerr[best].med_rel / cerr[best - 1].med_rel) / r;
    out.slope_max = std::log(cerr[best].max_rel_to_max / cerr[best - 1].max_rel_to_max) / r;
  }
  out.vlit_error = diffuse_error(values[1], ref).max_rel_to_max;
  out.calibration = cy.calibration;
  if (std::ifstream cli(o.blender_dir / "vlit-bake.txt"); cli) {
    std::ostringstream s;
    s << cli.rdbuf();
    out.cli_bake = s.str();
  }
  out.plot = ", \\\n     'data/end-to-end-cycles.dat' using 2:3 with linespoints pt 9 ps 1.5 title 'Cycles (comparison lights)', "
             "\\\n     '' using 2:3:1 with labels offset 1,-0.7 left font ',8' notitle, "
             "\\\n     'data/end-to-end-vlit-cycles-lights.dat' using 2:3 with points pt 13 ps 1.5 title 'vlit (comparison lights)', "
             "\\\n     '' using 2:3:1 with labels rotate by 30 offset 0.5,0.7 left font ',8' notitle";
  return out;
}

}  // namespace vlit::bench::accuracy
