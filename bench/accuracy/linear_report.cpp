// Accuracy report, linear light (Picott 1992 eq. 3-4 diffuse, eq. 7-8 peak specular; the exact
// specular of docs/conventions.md): every method on 1024 seeded ordinary segments (24 with
// --quick) and on the named stiff cases, in double and float, against the long-double Boost.Math
// reference in t (reference/linear_reference.h). The document's text about it: docs/accuracy.md.in.
#include <algorithm>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "linear_reference.h"

#include "accuracy_methods.h"
#include "case_grid.h"
#include "linear_light.h"
#include "report_format.h"
#include "reports.h"
#include "specular_rows.h"

namespace vlit::bench::accuracy {
namespace {

using linear_test::Config;
template <class T>
using LinX = linear_test::Typed<T>;

Config round_config(Config c) {
  c.p = to_float_grid(c.p);
  c.n = to_float_grid(normalize(c.n));
  c.rv = unit_on_float_grid(c.rv);
  c.q0 = to_float_grid(c.q0);
  c.q1 = to_float_grid(c.q1);
  c.shininess = double(float(c.shininess));
  return c;
}

// Ordinary: distance from P to the light's centre 1, length log-uniform in [0.1, 10] times the
// distance, P within 2 of the origin, normals and Rv biased towards the light, m log-uniform in
// [1, 1000].
std::vector<Config> ordinary_linear_configs(int count) {
  std::mt19937_64 rng(20240917);
  std::uniform_real_distribution<double> u01(0, 1);
  std::vector<Config> out;
  for (int i = 0; i < count; ++i) {
    Config c;
    const double distance = 2 * u01(rng);  // drawn first: the order GCC gave the unsequenced form
    c.p = random_unit(rng) * distance;
    const Vec3d centre = c.p + random_unit(rng);
    const double len = log_uniform(rng, -1, 1);
    const Vec3d dir = random_unit(rng);
    c.q0 = centre - dir * (len * u01(rng));
    c.q1 = c.q0 + dir * len;
    const Vec3d to_light = normalize(centre - c.p);
    std::tie(c.n, c.rv) = facing_light(to_light, 0.3, rng);
    c.shininess = log_uniform(rng, 0, 3);
    out.push_back(round_config(c));
  }
  return out;
}

struct StiffConfig {
  Config c;
  double falloff = 2;
};

struct NamedStiff {
  std::string name, text;
  std::vector<StiffConfig> configs;
};

std::vector<NamedStiff> stiff_linear_cases() {
  std::vector<NamedStiff> s;
  auto cfg = [](Vec3d p, Vec3d n, Vec3d rv, Vec3d q0, Vec3d q1, double m = 100, double falloff = 2) {
    Config c;
    c.p = p; c.n = n; c.rv = rv; c.q0 = q0; c.q1 = q1; c.shininess = m;
    return StiffConfig{round_config(c), falloff};
  };
  const Vec3d up{0, 1, 0};
  {
    NamedStiff k{"collinear", "P on the line of the segment, outside it (paper's 4CE - D^2 = 0)", {}};
    for (double n : {0.0, 1.0, 2.0, 3.0, 0.5, 2.5}) {
      k.configs.push_back(cfg({0, 0, 0}, {1, 1, 0}, {1, 0.1, 0}, {1, 0, 0}, {2, 0, 0}, 100, n));
      k.configs.push_back(cfg({0, 0, 0}, {-1, 0.2, 0.3}, {-1, 0, 0.05}, {-3, 0, 0}, {-0.5, 0, 0}, 100, n));
    }
    s.push_back(k);
  }
  {
    NamedStiff k{"near-collinear", "P at distance h = 1e-12 .. 1e-3 from the line, foot outside the segment", {}};
    for (double h : {1e-12, 1e-9, 1e-6, 1e-3})
      for (double n : {0.0, 2.0, 3.0, 1.5}) k.configs.push_back(cfg({0, h, 0}, {1, 1, 0}, {1, 0.01, 0}, {1, 0, 0}, {2, 0, 0}, 100, n));
    s.push_back(k);
  }
  {
    NamedStiff k{"far 1e6", "segment of length 1 at distance 1e6", {}};
    for (double n : {0.0, 1.0, 2.0, 3.0, 2.5}) {
      k.configs.push_back(cfg({0, 0, 0}, up, {0.3, 1, 0}, {-0.5, 1e6, 0}, {0.5, 1e6, 0}, 100, n));
      k.configs.push_back(cfg({0, 0, 0}, {0.2, 1, 0.1}, {0, 1, 0}, {1e6, 1e6, 0}, {1e6, 1e6 + 1, 0.5}, 1000, n));
    }
    s.push_back(k);
  }
  {
    NamedStiff k{"near 1e-6", "segment of length 1 at distance 1e-6 (foot inside and at an end)", {}};
    for (double n : {0.0, 1.0, 2.0, 3.0, 1.5}) {
      k.configs.push_back(cfg({0, 0, 0}, up, {0.1, 1, 0}, {-0.5, 1e-6, 0}, {0.5, 1e-6, 0}, 100, n));
      k.configs.push_back(cfg({0, 0, 0}, {0.3, 1, 0}, {0.5, 1, 0.2}, {0, 1e-6, 0}, {1, 1e-6, 0}, 100, n));
    }
    s.push_back(k);
  }
  {
    NamedStiff k{"grazing", "normal almost in the light's direction plane: L.N ~ 1e-6 |L|", {}};
    for (double n : {0.0, 2.0, 1.5}) {
      k.configs.push_back(cfg({0, 0, 0}, {0, 1e-6, 1}, {0, 1, 0.01}, {-1, 1, 0}, {1, 1, 0}, 10, n));
      k.configs.push_back(cfg({0, 0, 0}, {0, 1, 1e-6}, {0, 0.2, 1}, {-1, 0, 1}, {1, 1e-6, 1}, 10, n));
    }
    s.push_back(k);
  }
  {
    NamedStiff k{"crossing horizon", "segment crosses the tangent plane of P", {}};
    for (double n : {0.0, 1.0, 2.0, 3.0, 2.5}) {
      k.configs.push_back(cfg({0, 0, 0}, up, {0.2, 1, 0.5}, {-1, -1, 1}, {1, 1, 1}, 100, n));
      k.configs.push_back(cfg({0, 0, 0}, {0, 1, 0.3}, {0, 0.5, 1}, {0.2, 2, -1}, {0.3, -0.5, 2}, 100, n));
    }
    s.push_back(k);
  }
  {
    NamedStiff k{"endpoint on plane", "an endpoint exactly in the tangent plane of P", {}};
    for (double n : {0.0, 2.0, 0.5}) {
      k.configs.push_back(cfg({0, 0, 0}, up, {0.5, 1, 0.5}, {1, 0, 0.5}, {1, 1, 0.5}, 100, n));
      k.configs.push_back(cfg({0, 0, 0}, up, {0.0, 1, 0.0}, {-1, 0, 0}, {1, 0, 0.5}, 100, n));  // in the plane
    }
    s.push_back(k);
  }
  {
    NamedStiff k{"tiny 1e-9", "segment of length 1e-9 at distance 1 (point-light limit)", {}};
    for (double n : {0.0, 2.0, 3.0, 1.5})
      k.configs.push_back(cfg({0, 0, 0}, {0.2, 1, 0}, {0.1, 1, 0.1}, {0.3, 1, 0}, {0.3 + 1e-9, 1, 1e-9}, 100, n));
    s.push_back(k);
  }
  {
    NamedStiff k{"offset 1e4", "P and light 1e4 away from the origin, light at distance 1", {}};
    const Vec3d o{1e4, -1e4, 1e4};
    for (double n : {0.0, 2.0, 1.5}) {
      k.configs.push_back(cfg(o, up, {0.2, 1, 0}, o + Vec3d{-1, 1, 0}, o + Vec3d{1, 1, 0.5}, 100, n));
      k.configs.push_back(cfg(o, {0.3, 1, 0}, {0, 1, 0.2}, o + Vec3d{0, 1, -1}, o + Vec3d{0.1, 1.2, 1}, 100, n));
    }
    s.push_back(k);
  }
  {
    NamedStiff k{"shininess 1..1e4", "m = 1, 10, 100, 1e3, 1e4, lobe centred on and beside the light", {}};
    for (double m : {1.0, 10.0, 100.0, 1e3, 1e4}) {
      k.configs.push_back(cfg({0, 0, 0}, up, normalize(Vec3d{0.2, 1, 0}), {-1, 1, 0}, {1, 1, 0}, m));
      k.configs.push_back(cfg({0, 0, 0}, up, normalize(Vec3d{0.1, 1, 0.05}), {-1, 1, 0}, {1, 1, 0}, m));
      k.configs.push_back(cfg({0, 0, 0}, up, normalize(Vec3d{1.5, 1, 0}), {-1, 1, 0}, {1, 1, 0}, m));
    }
    s.push_back(k);
  }
  {
    NamedStiff k{"falloff 0..3", "n = 0, 0.5, 1, 1.5, 2, 2.5, 2.9, 3 at an ordinary distance", {}};
    for (double n : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 2.9, 3.0}) {
      k.configs.push_back(cfg({0, 0, 0}, up, {0.2, 1, 0}, {-1, 0.5, 0}, {2, 0.5, 0.3}, 100, n));
      k.configs.push_back(cfg({0, 0, 0}, {0.4, 1, 0}, {0, 1, 0.2}, {-0.2, 0.1, 0}, {0.2, 0.3, 0.1}, 100, n));
    }
    s.push_back(k);
  }
  return s;
}

enum class LinearQuantity { kDiffuse, kSpecular, kLobeMax };

LD linear_reference(const Config& c, double falloff, LinearQuantity q) {
  const auto x = linear_test::typed<double>(c, falloff);
  switch (q) {
    case LinearQuantity::kDiffuse: return linear_test::ref_diffuse(x);
    case LinearQuantity::kSpecular: return linear_test::ref_specular_exact(x);
    default: return linear_test::ref_specular_peak(x);
  }
}

CaseSet<LinX> linear_set(const std::vector<Config>& cs, const std::vector<double>& falloff, LinearQuantity q,
                         const std::vector<int>& group = {}) {
  CaseSet<LinX> s;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    s.d.push_back(linear_test::typed<double>(cs[i], falloff[i]));
    s.f.push_back(linear_test::typed<float>(cs[i], falloff[i]));
    s.ref.push_back(linear_reference(cs[i], falloff[i], q));
  }
  s.group = group;
  set_floors(s);
  return s;
}

CaseSet<LinX> linear_stiff_set(const std::vector<NamedStiff>& named, LinearQuantity q) {
  std::vector<Config> cs;
  std::vector<double> fo;
  std::vector<int> group;
  for (std::size_t g = 0; g < named.size(); ++g)
    for (const StiffConfig& sc : named[g].configs) {
      cs.push_back(sc.c);
      fo.push_back(sc.falloff);
      group.push_back(int(g));
    }
  CaseSet<LinX> s = linear_set(cs, fo, q, group);
  for (const NamedStiff& n : named) { s.group_names.push_back(n.name); s.group_text.push_back(n.text); }
  return s;
}

}  // namespace

LinearSections linear_report(const Options& o) {
  LinearSections out;
  const int count = o.quick ? 24 : 1024;
  const std::vector<Config> ord = ordinary_linear_configs(count);
  progress("linear: references for " + std::to_string(count) + " ordinary cases");
  std::map<double, CaseSet<LinX>> diff;  // by falloff n
  for (double n : {0.0, 1.0, 2.0, 3.0, 1.5}) diff[n] = linear_set(ord, std::vector<double>(ord.size(), n), LinearQuantity::kDiffuse);
  const std::vector<NamedStiff> named = stiff_linear_cases();
  const CaseSet<LinX> stiff_d = linear_stiff_set(named, LinearQuantity::kDiffuse);

  out.diffuse = make_section("linear-diffuse", "Linear light, diffuse", count, stiff_d);
  Section& sd = out.diffuse;
  progress("linear diffuse methods");
  auto is_integer = [](const auto& x) { const double n = double(x.light.falloff); return n == 0 || n == 1 || n == 2 || n == 3; };
  auto closed = [](const auto& x, std::size_t) {
    return linear_diffuse_closed(x.light, x.sp, int(x.light.falloff));
  };
  for (double n : {0.0, 1.0, 2.0, 3.0}) {
    char name[64];
    std::snprintf(name, sizeof name, "closed form n=%g", n);
    method(sd, o, "closed-n" + fmt_ns(n), name, "n=" + fmt_ns(n), "stable closed form; no tolerance (rounding only)", diff[n],
           n == 2 ? &stiff_d : nullptr, closed, is_integer, n == 2);
  }
  const CaseSet<LinX>& d2 = diff[2.0];
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    char name[64];
    std::snprintf(name, sizeof name, "adaptive GL tol %g%s", tol, tol == 1e-10 ? " (default)" : "");
    auto quad = [tol](const auto& x, std::size_t) { return linear_diffuse_quadrature(x.light, x.sp, tol); };
    char promise[96];
    std::snprintf(promise, sizeof promise, "relative %g (8/16-point panel difference)", tol);
    method(sd, o, "adaptive-" + tol_key(tol) + "-n2", name, "n=2 forced", promise, d2, &stiff_d, quad, kAlways);
    method(sd, o, "adaptive-" + tol_key(tol) + "-n1.5", name, "n=1.5", promise, diff[1.5], static_cast<const CaseSet<LinX>*>(nullptr), quad, kAlways, false);
  }
  for (int order : {8, 16, 32, 64}) {
    const FixedRule rule = make_fixed_rule(order);
    auto gl = [&rule](const auto& x, std::size_t) {
      using T = std::decay_t<decltype(x.light.falloff)>;
      const LinearT<T> g = linear_t(x.light, x.sp);
      if (!g.visible) return T(0);
      return fixed_gauss(rule, g.ta, g.tb, [&](T t) { return linear_diffuse_integrand(g, x.sp, x.light.falloff, t); });
    };
    method(sd, o, "fixed-gl-" + std::to_string(order), "fixed GL " + std::to_string(order) + " points", "n=2", "none (no error estimate)", d2, &stiff_d, gl, kAlways);
  }
  monte_carlo_rows(sd, o, "n=2", "statistical, ~1/sqrt(N)", "statistical, ~1/sqrt(N) or better", {16, 64, 256, 1024, 4096},
                   d2, &stiff_d, [](int n, bool strat) {
                     return [n, strat](const auto& x, std::size_t i) {
                       using T = std::decay_t<decltype(x.light.falloff)>;
                       const LinearT<T> g = linear_t(x.light, x.sp);
                       if (!g.visible) return T(0);
                       return monte_carlo_1d<T>(0x5eed + i, n, strat, g.ta, g.tb,
                                                [&](T t) { return linear_diffuse_integrand(g, x.sp, x.light.falloff, t); });
                     };
                   });

  // Specular.
  progress("linear specular references");
  const CaseSet<LinX> sp = linear_set(ord, std::vector<double>(ord.size(), 2.0), LinearQuantity::kSpecular);
  const CaseSet<LinX> sp_max = linear_set(ord, std::vector<double>(ord.size(), 2.0), LinearQuantity::kLobeMax);
  const CaseSet<LinX> stiff_s = linear_stiff_set(named, LinearQuantity::kSpecular);
  out.specular = make_section("linear-specular", "Linear light, specular", count, stiff_s);
  Section& ss = out.specular;
  auto spec_with = [](SpecularOptions opt) {
    return [opt](const auto& x, std::size_t) { return shade_linear(x.light, x.sp, opt).specular; };
  };
  specular_method_rows(ss, o, sp, &stiff_s, "mean lobe near the peak (not the integral)", {1e-3, 1e-6, 1e-9, 1e-12},
                       "closed forms within their bounds, else K15 vs G7", spec_with);
  for (int order : {16, 64}) {
    const FixedRule rule = make_fixed_rule(order);
    auto gl = [&rule](const auto& x, std::size_t) {
      using T = std::decay_t<decltype(x.light.falloff)>;
      const LinearT<T> g = linear_t(x.light, x.sp);
      if (!g.visible) return T(0);
      return fixed_gauss(rule, g.ta, g.tb, [&](T t) { return linear_specular_integrand(g, x.sp, t); });
    };
    method(ss, o, "fixed-gl-" + std::to_string(order), "fixed GL " + std::to_string(order) + " points", "m 1..1e3", "none", sp, &stiff_s, gl, kAlways);
  }
  monte_carlo_rows(ss, o, "m 1..1e3", "statistical", "statistical", {16, 256, 4096}, sp, &stiff_s, [](int n, bool strat) {
    return [n, strat](const auto& x, std::size_t i) {
      using T = std::decay_t<decltype(x.light.falloff)>;
      const LinearT<T> g = linear_t(x.light, x.sp);
      if (!g.visible) return T(0);
      return monte_carlo_1d<T>(0x5eed + i, n, strat, g.ta, g.tb, [&](T t) { return linear_specular_integrand(g, x.sp, t); });
    };
  });
  // What the peak estimates: the lobe's maximum (reference: dense search + golden section, t).
  {
    SpecularOptions peak;
    peak.method = SpecularMethod::kPeak;
    Section tmp;
    method(tmp, o, "peak-vs-lobe-maximum", "peak vs lobe maximum", "m 1..1e3", "", sp_max, static_cast<const CaseSet<LinX>*>(nullptr), spec_with(peak), kAlways);
    std::vector<double> ratio;
    for (std::size_t i = 0; i < sp.ref.size(); ++i)
      if (sp.ref[i] > 0) ratio.push_back(double(sp_max.ref[i] / sp.ref[i]));
    std::sort(ratio.begin(), ratio.end());
    out.peak_vs_max = tmp.rows[0].d;
    out.peak_vs_max_float = tmp.rows[0].f;
    out.specular.nonfinite += tmp.nonfinite;
    out.ratio_count = ratio.size();
    if (!ratio.empty()) {
      out.ratio_min = ratio.front();
      out.ratio_med = ratio[ratio.size() / 2];
      out.ratio_max = ratio.back();
    }
  }
  return out;
}

}  // namespace vlit::bench::accuracy
