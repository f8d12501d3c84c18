// Area and disk lights: evaluations per second of each method, against the cheapest Gauss product
// rule of equal accuracy, one core, one run of this program.
//
//   cmake --build build/release --target area_light_bench -j2 && ./build/release/bench/area_light_bench [--quick]
//   ./build/release/bench/area_light_bench --closed-by-m [--tails] [--quick]   (the closed forms at fixed m: closed_by_m;
//   --tails aims Rv mostly beside the light)
//
// Shapes: triangle, quad, regular 8-gon, disk (size 0.3..1.2 at distance 1..3 from P, emitting
// toward P, N toward the light so the whole light is above the horizon: the quadrature's best case,
// no kink of max(0, .) inside the light). For each shape 128 seeded cases; errors against the
// long-double Boost.Math references (reference/area_reference.h, disk_reference.h).
// Diffuse: the closed forms (contour, eq. 9; the disk's analytic contour) against a Gauss-Legendre
// product rule over the light (polygons: fan triangles, Duffy-collapsed n x n rule; disk: polar
// n x 2n rule), whose order n is raised until its max error over the cases is <= 10x the closed
// form's (both then at rounding level; or n = 64). Specular: the peak, the neighbourhood (K = 4) and the exact lobe integral at tol
// 1e-6 and 1e-9, against the product rule of the lobe integrand raised to the exact method's error.
// The exact rows use the closed form (area_specular_closed.h) where it is within its bound; two
// more rows time the closed form alone and the adaptive form alone on the same cases.
// Times: ns per evaluation (per-light preparation excluded, as in the bake loop), best of 3 passes
// over the cases, each pass repeated until it takes >= 50 ms (2 ms with --quick); single thread.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "area_reference.h"
#include "disk_reference.h"

#include "accuracy_methods.h"
#include "area_light.h"
#include "area_specular_closed_real.h"
#include "area_specular_tail.h"
#include "disk_light.h"

namespace {

using namespace vlit;
using LD = long double;

struct Case {
  std::vector<Vec3d> polygon;  // empty for a disk
  DiskLight<double> disk;
  PreparedAreaLight<double> prepared;
  PreparedDiskLight<double> prepared_disk;
  ShadingPoint<double> sp;
  LD ref_diffuse = 0, ref_specular = 0;
};

Vec3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Vec3d v{g(rng), g(rng), g(rng)};
    if (length(v) > 1e-3) return normalize(v);
  }
}

// sides: 3, 4, 8, or 0 for a disk.
// real_m: the same cases with m = 10^(3u) not rounded (glTF roughness gives real m).
// references = false leaves ref_diffuse and ref_specular 0 (timing only).
// rv_spread: how far Rv strays from the direction toward the light's centre (0.3: mostly through
// the light; 1: mostly beside it, the lobe's tail).
std::vector<Case> make_cases(int sides, int count, bool real_m = false, bool references = true, double rv_spread = 0.3) {
  std::mt19937_64 rng(1000 + sides);
  std::uniform_real_distribution<double> u01(0, 1);
  std::vector<Case> out;
  while (int(out.size()) < count) {
    Case c;
    const double distance = u01(rng);  // drawn first: the order GCC gave the unsequenced form
    const Vec3d p = random_unit(rng) * distance;
    const Vec3d to_light = random_unit(rng);
    const Vec3d center = p + to_light * (1 + 2 * u01(rng));
    const Vec3d normal = normalize(-to_light + random_unit(rng) * 0.5);  // emits toward P
    const double size = 0.3 + 0.9 * u01(rng);
    const Vec3d helper = std::abs(normal.x) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    const Vec3d e1 = normalize(cross(helper, normal)), e2 = cross(normal, e1);
    const Vec3d n = normalize(to_light + random_unit(rng) * 0.3);
    const Vec3d rv = normalize(to_light + random_unit(rng) * rv_spread);
    const double m_real = std::pow(10.0, 3 * u01(rng));
    const double m = real_m ? m_real : std::round(m_real);
    c.sp = {p, n, rv, m};
    if (sides == 0) {
      c.disk = {center, normal, size};
      c.prepared_disk = prepare_disk_light(c.disk);
    } else {
      const double phase = 2 * M_PI * u01(rng);
      for (int k = 0; k < sides; ++k) {
        const double a = phase + 2 * M_PI * k / sides;
        c.polygon.push_back(center + e1 * (size * std::cos(a)) + e2 * (size * std::sin(a)));
      }
      AreaLight<double> l;
      l.polygon = c.polygon;
      c.prepared = prepare_area_light(l);
    }
    // Whole light above the horizon of P (the product rule's best case).
    bool above = true;
    if (sides == 0) {
      const double nd = dot(n, center - p), mu = length(n - normal * dot(n, normal));
      above = nd > size * mu;
    } else {
      for (const Vec3d& q : c.polygon) above = above && dot(n, q - p) > 0;
    }
    if (!above) continue;
    if (!references) {
      out.push_back(c);
      continue;
    }
    if (sides == 0) {
      test::DiskQuery q;
      q.center = center; q.normal = normal; q.radius = size; q.p = p; q.n = n; q.rv = rv; q.m = m;
      c.ref_diffuse = test::disk_reference(q);
      q.specular = true;
      c.ref_specular = test::disk_reference(q);
    } else {
      test::RefQuery q;
      q.pieces = {c.polygon};
      q.p = p; q.n = n; q.rv = rv; q.m = m;
      q.tolerance = 1e-13L;
      c.ref_diffuse = test::reference_integral(q);
      q.specular = true;
      c.ref_specular = test::reference_integral(q);
    }
    out.push_back(c);
  }
  return out;
}

// Gauss-Legendre product rules of order n (nodes on [0, 1]).
struct Rule {
  std::vector<double> x, w;
};
Rule unit_rule(int n) {
  const bench::FixedRule r = bench::make_fixed_rule(n);
  Rule u;
  for (std::size_t i = 0; i < r.x.size(); ++i) { u.x.push_back((r.x[i] + 1) / 2); u.w.push_back(r.w[i] / 2); }
  return u;
}

// Integrand at the light point x: diffuse cos(theta) cos(theta_l) / r^2, specular lobe cos(theta_l) / r^2.
double integrand(const Vec3d& x, const Vec3d& light_normal, const ShadingPoint<double>& sp, bool specular) {
  const Vec3d a = x - sp.p;
  const double r2 = dot(a, a), r = std::sqrt(r2);
  const double cos_l = -dot(light_normal, a) / r;
  const double cos_n = dot(sp.n, a) / r;
  if (!(cos_l > 0) || !(cos_n > 0)) return 0;
  if (!specular) return cos_n * cos_l / r2;
  const double c = dot(sp.rv, a) / r;
  return (c > 0 ? std::pow(c, sp.shininess) : 0.0) * cos_l / r2;
}

double product_rule(const Case& c, const Rule& rule, bool specular) {
  double sum = 0;
  const int n = int(rule.x.size());
  if (c.polygon.empty()) {  // polar over the disk: n radial x 2n angular (midpoint in angle: periodic)
    const Vec3d nl = normalize(c.disk.normal);
    const Vec3d helper = std::abs(nl.x) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    const Vec3d e1 = normalize(cross(helper, nl)), e2 = cross(nl, e1);
    const int na = 2 * n;
    for (int j = 0; j < na; ++j) {
      const double phi = 2 * M_PI * (j + 0.5) / na;
      const Vec3d dir = e1 * std::cos(phi) + e2 * std::sin(phi);
      for (int i = 0; i < n; ++i) {
        const double rho = rule.x[i] * c.disk.radius;
        sum += rule.w[i] * rho * integrand(c.disk.center + dir * rho, nl, c.sp, specular);
      }
    }
    return sum * c.disk.radius * 2 * M_PI / na;
  }
  const Vec3d nl = c.prepared.normal;
  const Vec3d& q0 = c.polygon[0];
  for (std::size_t t = 1; t + 1 < c.polygon.size(); ++t) {
    const Vec3d e1 = c.polygon[t] - q0, e2 = c.polygon[t + 1] - q0;
    const double jac = length(cross(e1, e2));
    double tri = 0;
    for (int i = 0; i < n; ++i) {
      const double s = rule.x[i];
      double inner = 0;
      for (int j = 0; j < n; ++j) inner += rule.w[j] * integrand(q0 + (e1 + (e2 - e1) * rule.x[j]) * s, nl, c.sp, specular);
      tri += rule.w[i] * s * inner;
    }
    sum += tri * jac;
  }
  return sum;
}

double rel_err(double v, LD ref) { return double(std::fabs(LD(v) - ref) / std::max(std::fabs(ref), LD(1e-300))); }

double g_sink = 0;
double g_pass_ns = 5e7;  // each timing pass repeats until this long (--quick: 2 ms, a run check only)

// ns per evaluation: best of 3 passes, each repeated until >= g_pass_ns.
double time_ns(const std::vector<Case>& cases, const std::function<double(const Case&)>& f) {
  double best = INFINITY;
  for (int pass = 0; pass < 3; ++pass) {
    int reps = 0;
    const auto t0 = std::chrono::steady_clock::now();
    double elapsed = 0;
    do {
      for (const Case& c : cases) g_sink += f(c);
      ++reps;
      elapsed = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
    } while (elapsed < g_pass_ns);
    best = std::min(best, elapsed / (double(reps) * double(cases.size())));
  }
  return best;
}

double max_error(const std::vector<Case>& cases, const std::function<double(const Case&)>& f, bool specular) {
  double worst = 0;
  for (const Case& c : cases) worst = std::max(worst, rel_err(f(c), specular ? c.ref_specular : c.ref_diffuse));
  return worst;
}

// Smallest product-rule order whose max error is <= target (or 64).
int matching_order(const std::vector<Case>& cases, double target, bool specular, double* err_out) {
  for (int n = 1; n <= 64; n += (n < 16 ? 1 : 4)) {
    const Rule rule = unit_rule(n);
    const double err = max_error(cases, [&](const Case& c) { return product_rule(c, rule, specular); }, specular);
    if (err <= target || n == 64) { *err_out = err; return n; }
  }
  return 64;
}

std::string ratio(double r) {
  char b[32];
  std::snprintf(b, sizeof b, r < 10 ? "%.1fx" : "%.0fx", r);
  return b;
}

void row(const char* shape, const char* method, double err, double ns, double baseline_ns, const std::string& note) {
  char rate[32];
  if (ns < 1e3) std::snprintf(rate, sizeof rate, "%.2f M", 1e3 / ns);
  else std::snprintf(rate, sizeof rate, "%.1f k", 1e6 / ns);
  std::printf("| %s | %s | %.1e | %.0f | %s | %s | %s |\n", shape, method, err, ns, rate,
              baseline_ns > 0 ? ratio(baseline_ns / ns).c_str() : "—", note.c_str());
}

// --closed-by-m: the integer-m closed form (area_specular_closed.h) alone, the tail closed form
// (area_specular_tail.h) alone on the cases it accepts (Rv off the light), the adaptive form
// (area_specular_exact.h, tol 1e-9) alone, and the exact specular's dispatch (area_light.h: the
// narrow lobe's cap above kAreaCapDispatchMinShininess, the edge lobe above
// kAreaEdgeLobeDispatchMinShininess, closed, tail, else adaptive) against closed, else adaptive,
// and against the dispatch without the edge lobe, at fixed m on each polygon's cases (m replaced); with how many cases each closed form
// accepts and its largest difference from the adaptive form at tol 1e-13 (relative tolerance
// only) on those (their accuracy against the
// Boost.Math references is tests/kernels/area/area_specular_closed_test.cpp's and
// area_specular_tail_test.cpp's). Issue 21's scalar bar: <= 500 ns per evaluation for m <= 100,
// <= 2 us up to m = 1e4.
int closed_by_m(int count, double rv_spread) {
  std::printf("| shape | m | closed form alone ns/eval | accepted | tail form alone ns/eval (on its accepted cases) | adaptive alone on those ns/eval | tail accepted | adaptive alone tol 1e-9 ns/eval | exact: closed, else adaptive ns/eval | exact: the dispatch without the edge lobe (cap, closed, tail, adaptive) ns/eval | exact: the dispatch (cap, edge lobe, closed, tail, adaptive) ns/eval | max rel. diff vs adaptive: closed, tail (accepted) | cap accepted (dispatched above m = %g) | edge lobe accepted where the cap refuses (dispatched above m = %g) |\n", kAreaCapDispatchMinShininess, kAreaEdgeLobeDispatchMinShininess);
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const struct { int sides; const char* name; } shapes[] = {{3, "triangle"}, {4, "quad"}, {8, "8-gon"}};
  struct Visible {
    AreaView<double> view;
    ClipPolygon<double> polygon;
  };
  for (const auto& shape : shapes) {
    const std::vector<Case> base = make_cases(shape.sides, count, false, false, rv_spread);
    for (int m : {0, 1, 2, 10, 30, 100, 300, 1000, 3000, 10000}) {
      std::vector<Case> cases = base;
      for (Case& c : cases) c.sp.shininess = m;
      std::vector<Visible> visible(cases.size());
      for (std::size_t i = 0; i < cases.size(); ++i) {
        visible[i].view = make_area_view(cases[i].prepared, cases[i].sp.p);
        if (visible[i].view.lit) clip_to_horizon(cases[i].prepared, visible[i].view, cases[i].sp.n, visible[i].polygon);
      }
      // Each form from the horizon-clipped polygon, as the dispatch calls it.
      const auto with = [](const std::vector<Case>& of, const std::vector<Visible>& vis, auto form) {
        return [&of, &vis, form](const Case& c) {
          const Visible& v = vis[std::size_t(&c - of.data())];
          return form(v, c);
        };
      };
      const auto closed_form = [m](const Visible& v, const Case& c) {
        return area_specular_closed(v.polygon, v.view, c.sp.rv, m).value;
      };
      const auto tail_form = [m](const Visible& v, const Case& c) {
        return area_specular_tail(v.polygon, v.view, c.sp.rv, double(m)).value;
      };
      const auto adaptive_form = [m](const Visible& v, const Case& c) {
        return area_specular_exact(v.polygon, v.view, c.sp.rv, double(m), 1e-9);
      };
      const auto without_tail = [m](const Visible& v, const Case& c) {
        if (m <= kAreaClosedDispatchMaxShininess) {
          const AreaSpecularClosed<double> r = area_specular_closed(v.polygon, v.view, c.sp.rv, m);
          if (r.accepted) return r.value;
        }
        return area_specular_exact(v.polygon, v.view, c.sp.rv, double(m), 1e-9);
      };
      const auto dispatch = [m](const Visible& v, const Case& c) {  // cap, edge lobe, closed, tail, adaptive
        return area_specular_exact_dispatch(v.polygon, v.view, c.sp.rv, double(m), 1e-9);
      };
      const auto without_edge_lobe = [m](const Visible& v, const Case& c) {  // the dispatch before the edge lobe
        if (m > kAreaCapDispatchMinShininess) {
          const AreaSpecularClosed<double> r = area_specular_cap(v.polygon, v.view, c.sp.rv, double(m));
          if (r.accepted) return r.value;
        }
        if (m <= kAreaClosedDispatchMaxShininess) {
          const AreaSpecularClosed<double> r = area_specular_closed(v.polygon, v.view, c.sp.rv, m);
          if (r.accepted) return r.value;
        }
        if (m <= kAreaTailDispatchMaxShininess) {
          const double floor = 1e-9 * std::numeric_limits<double>::epsilon() * 2 * M_PI / (m + 1);
          const AreaSpecularClosed<double> r = area_specular_tail(v.polygon, v.view, c.sp.rv, double(m), floor);
          if (r.accepted) return r.value;
        }
        return area_specular_exact(v.polygon, v.view, c.sp.rv, double(m), 1e-9);
      };
      int accepted = 0, tail_accepted = 0, cap_accepted = 0, edge_accepted = 0;
      double worst = 0, worst_tail = 0;
      std::vector<Case> tails;
      std::vector<Visible> tails_visible;
      for (std::size_t i = 0; i < cases.size(); ++i) {
        const Visible& v = visible[i];
        // relative tolerance only (bounded_tails = false): the default's absolute target leaves
        // values ~1e-30 at m = 100 a few digits off, which the tail form resolves
        const double ref = area_specular_exact(v.polygon, v.view, cases[i].sp.rv, double(m), 1e-13, false);
        auto diff = [&](double value) { return ref != 0 ? std::fabs(value - ref) / std::fabs(ref) : 0.0; };
        const AreaSpecularClosed<double> r = area_specular_closed(v.polygon, v.view, cases[i].sp.rv, m);
        if (r.accepted) {
          ++accepted;
          worst = std::max(worst, diff(r.value));
        }
        const bool cap = area_specular_cap(v.polygon, v.view, cases[i].sp.rv, double(m)).accepted;
        cap_accepted += cap;
        // the edge lobe where the dispatch would reach it (the cap refused)
        edge_accepted += !cap && area_specular_edge_lobe(v.polygon, v.view, cases[i].sp.rv, double(m)).accepted;
        const AreaSpecularClosed<double> t = area_specular_tail(v.polygon, v.view, cases[i].sp.rv, double(m));
        if (t.accepted) {
          ++tail_accepted;
          worst_tail = std::max(worst_tail, diff(t.value));
          tails.push_back(cases[i]);
          tails_visible.push_back(v);
        }
      }
      const double tail_ns = tails.empty() ? 0 : time_ns(tails, with(tails, tails_visible, tail_form));
      const double tails_adaptive_ns = tails.empty() ? 0 : time_ns(tails, with(tails, tails_visible, adaptive_form));
      std::printf("| %s | %d | %.0f | %d / %d | %.0f | %.0f | %d / %d | %.0f | %.0f | %.0f | %.0f | %.1e, %.1e | %d / %d | %d / %d |\n", shape.name, m,
                  time_ns(cases, with(cases, visible, closed_form)), accepted, int(cases.size()), tail_ns, tails_adaptive_ns, tail_accepted,
                  int(cases.size()), time_ns(cases, with(cases, visible, adaptive_form)),
                  time_ns(cases, with(cases, visible, without_tail)), time_ns(cases, with(cases, visible, without_edge_lobe)),
                  time_ns(cases, with(cases, visible, dispatch)), worst, worst_tail, cap_accepted, int(cases.size()),
                  edge_accepted, int(cases.size()));
      std::fflush(stdout);
    }
  }
  std::fprintf(stderr, "(checksum %g)\n", g_sink);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  bool by_m = false, quick = false, tails = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--closed-by-m") == 0) by_m = true;
    else if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    else if (std::strcmp(argv[i], "--tails") == 0) tails = true;
    else return std::fprintf(stderr, "usage: area_light_bench [--closed-by-m [--tails]] [--quick]\n"), 2;
  }
  if (quick) g_pass_ns = 2e6;
  if (by_m) return closed_by_m(quick ? 4 : 128, tails ? 1.0 : 0.3);
  const int count = quick ? 4 : 128;
  std::printf("| shape | method | max rel. error | ns/eval | evals/s | speed-up vs matching product rule | product rule |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  const struct { int sides; const char* name; } shapes[] = {{3, "triangle"}, {4, "quad"}, {8, "8-gon"}, {0, "disk"}};
  for (const auto& shape : shapes) {
    std::fprintf(stderr, "%s: references for %d cases ...\n", shape.name, count);
    const std::vector<Case> cases = make_cases(shape.sides, count);
    const bool disk = shape.sides == 0;
    auto shade = [&](SpecularMethod method, double tol, int k) {
      SpecularOptions o;
      o.method = method;
      o.exact_tolerance = tol;
      o.neighborhood_samples = k;
      return [o, disk](const Case& c) {
        const Response<double> r = disk ? shade_disk(c.prepared_disk, c.sp, o) : shade_area(c.prepared, c.sp, o);
        return o.method == SpecularMethod::kNone ? r.diffuse : r.specular;
      };
    };
    // Diffuse
    const auto closed = shade(SpecularMethod::kNone, 0, 0);
    const double closed_err = max_error(cases, closed, false);
    double gl_err = 0;
    const int order = matching_order(cases, 10 * closed_err, false, &gl_err);  // both at rounding level
    const Rule rule = unit_rule(order);
    const double gl_ns = time_ns(cases, [&](const Case& c) { return product_rule(c, rule, false); });
    const double closed_ns = time_ns(cases, closed);
    row(shape.name, disk ? "diffuse, analytic contour" : "diffuse, contour (eq. 9)", closed_err, closed_ns, gl_ns, "");
    const std::string rule_name = disk ? "polar " + std::to_string(order) + "x" + std::to_string(2 * order)
                                       : std::to_string(order) + "x" + std::to_string(order) + " per fan triangle";
    row(shape.name, ("diffuse, Gauss product " + rule_name).c_str(), gl_err, gl_ns, 0,
        order == 64 && gl_err > 10 * closed_err ? "order cap 64 reached" : "");
    // Specular
    const auto peak = shade(SpecularMethod::kPeak, 0, 0);
    row(shape.name, "specular, peak (not the integral)", max_error(cases, peak, true), time_ns(cases, peak), 0, "");
    const auto nb = shade(SpecularMethod::kNeighborhood, 0, 4);
    row(shape.name, "specular, neighbourhood K=4 (not the integral)", max_error(cases, nb, true), time_ns(cases, nb), 0, "");
    for (double tol : {1e-6, 1e-9}) {
      const auto ex = shade(SpecularMethod::kExact, tol, 0);
      const double ex_err = max_error(cases, ex, true);
      double sgl_err = 0;
      const int sorder = matching_order(cases, ex_err, true, &sgl_err);
      const Rule srule = unit_rule(sorder);
      const double sgl_ns = time_ns(cases, [&](const Case& c) { return product_rule(c, srule, true); });
      char name[64];
      std::snprintf(name, sizeof name, "specular, exact tol %g", tol);
      row(shape.name, name, ex_err, time_ns(cases, ex), sgl_ns, "");
      const std::string sname = "specular, Gauss product " + (disk ? "polar " + std::to_string(sorder) + "x" + std::to_string(2 * sorder)
                                                                     : std::to_string(sorder) + "x" + std::to_string(sorder));
      row(shape.name, sname.c_str(), sgl_err, sgl_ns, 0, sorder == 64 && sgl_err > ex_err ? "order cap 64 reached" : "");
    }
    if (!disk) {
      // The exact specular's engines on the same cases (integer m in [1, 1e3]): the closed form
      // alone (area_specular_closed.h, forced even where its bound refuses it) and the adaptive
      // form alone (area_specular_exact.h, tol 1e-9); `exact` above dispatches between them.
      auto engine = [](bool closed_form) {
        return [closed_form](const Case& c) {
          const AreaView<double> view = make_area_view(c.prepared, c.sp.p);
          if (!view.lit) return 0.0;
          ClipPolygon<double> visible;
          clip_to_horizon(c.prepared, view, c.sp.n, visible);
          if (visible.count < 3) return 0.0;
          return closed_form ? area_specular_closed(visible, view, c.sp.rv, int(c.sp.shininess)).value
                             : area_specular_exact(visible, view, c.sp.rv, c.sp.shininess, 1e-9);
        };
      };
      int accepted = 0;
      for (const Case& c : cases) {
        const AreaView<double> view = make_area_view(c.prepared, c.sp.p);
        ClipPolygon<double> visible;
        if (view.lit) clip_to_horizon(c.prepared, view, c.sp.n, visible);
        if (!view.lit || visible.count < 3 || area_specular_closed(visible, view, c.sp.rv, int(c.sp.shininess)).accepted) ++accepted;
      }
      char note[64];
      std::snprintf(note, sizeof note, "within its bound on %d of %d cases", accepted, int(cases.size()));
      const auto cf = engine(true), ad = engine(false);
      row(shape.name, "specular, closed form alone (integer m, forced)", max_error(cases, cf, true), time_ns(cases, cf), 0, note);
      row(shape.name, "specular, adaptive form alone tol 1e-9", max_error(cases, ad, true), time_ns(cases, ad), 0, "");

      // Real m in [1, 1e3] (not rounded): `exact` (the adaptive form for real m), the real-m closed
      // form alone (area_specular_closed_real.h, forced; not dispatched) and the adaptive form
      // alone; speed-up against the adaptive form alone.
      const std::vector<Case> real_cases = make_cases(shape.sides, count, true);
      auto real_engine = [](bool closed_form) {
        return [closed_form](const Case& c) {
          const AreaView<double> view = make_area_view(c.prepared, c.sp.p);
          if (!view.lit) return 0.0;
          ClipPolygon<double> visible;
          clip_to_horizon(c.prepared, view, c.sp.n, visible);
          if (visible.count < 3) return 0.0;
          return closed_form ? area_specular_closed_real(visible, view, c.sp.rv, c.sp.shininess).value
                             : area_specular_exact(visible, view, c.sp.rv, c.sp.shininess, 1e-9);
        };
      };
      int real_accepted = 0;
      for (const Case& c : real_cases) {
        const AreaView<double> view = make_area_view(c.prepared, c.sp.p);
        ClipPolygon<double> visible;
        if (view.lit) clip_to_horizon(c.prepared, view, c.sp.n, visible);
        if (!view.lit || visible.count < 3 || area_specular_closed_real(visible, view, c.sp.rv, c.sp.shininess).accepted) ++real_accepted;
      }
      std::snprintf(note, sizeof note, "within its estimate on %d of %d cases", real_accepted, int(real_cases.size()));
      const auto rex = shade(SpecularMethod::kExact, 1e-9, 0);
      const auto rcf = real_engine(true), rad = real_engine(false);
      const double rad_ns = time_ns(real_cases, rad);
      row(shape.name, "specular, exact tol 1e-9 (real m)", max_error(real_cases, rex, true), time_ns(real_cases, rex), rad_ns, "vs adaptive alone");
      row(shape.name, "specular, real closed form alone (real m, forced)", max_error(real_cases, rcf, true), time_ns(real_cases, rcf), rad_ns, note);
      row(shape.name, "specular, adaptive form alone tol 1e-9 (real m)", max_error(real_cases, rad, true), rad_ns, 0, "");
    }
  }
  std::fprintf(stderr, "(checksum %g)\n", g_sink);
  return 0;
}
