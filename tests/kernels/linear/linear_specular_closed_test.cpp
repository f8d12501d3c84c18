// The closed form for integer m (linear_specular_closed.h) against the independent long-double
// Boost.Math reference (linear_reference.h, parametrised in t, not in the kernel's angle), for
// the falloff n = 2 on the specular (the definition) and n = 0 (the paper's form), against
// the adaptive form (linear_specular_exact.h) in the same test, on seeded log-uniform random
// configurations and on named stiff cases; and the acceptance bound: where the recurrence loses
// digits it says so (accepted = false) and `--specular exact` uses the adaptive form there.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "linear_cases.h"
#include "linear_specular_closed.h"

using namespace vlit;
using namespace vlit::linear_test;

namespace {

constexpr double kOrdinaryBar = 1e-12;  // accepted closed form vs the reference, random cases
constexpr double kStiffBar = 1e-9;      // `--specular exact` (closed or adaptive) on the stiff cases

// Both falloffs on the specular: n = 2 (the radiometric definition for an inverse-square light)
// and n = 0 (the paper's form). The light's falloff is n, so the reference integrates 1/|L|^n.
constexpr int kFalloffs[] = {2, 0};

LinearFrame<double> frame_of(const Config& c, int n) {
  const Typed<double> x = typed<double>(c, n);
  return make_linear_frame_precise(x.light, x.sp);
}

// The closed form in world units (the frame's value times scale^-n).
LinearSpecularClosed<double> closed(const Config& c, int m, int n) {
  const LinearFrame<double> fr = frame_of(c, n);
  LinearSpecularClosed<double> k = linear_specular_closed_frame(fr, m, n);
  k.value *= linear_scale_factor(fr.scale, n);
  return k;
}

double adaptive(const Config& c, double tol, int n) {
  const LinearFrame<double> fr = frame_of(c, n);
  return linear_specular_exact_frame(fr, c.shininess, tol, double(n)) * linear_scale_factor(fr.scale, n);
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

TEST_CASE("closed-form linear specular: random configurations vs the Boost.Math reference") {
  for (const int n : kFalloffs) {
  int accepted = 0, total = 0;
  double worst = 0, worst_vs_adaptive = 0, worst_ratio = 0;
  std::string worst_where;
  for (uint64_t seed = 1; seed <= 2000; ++seed) {
    Config c = random_config(seed);
    c.shininess = std::max(1.0, std::round(c.shininess));  // integer m in [1, 1000], log-uniform
    const int m = int(c.shininess);
    const LinearSpecularClosed<double> k = closed(c, m, n);
    CHECK(std::isfinite(k.value));
    ++total;
    if (!k.accepted) continue;
    ++accepted;
    const LD ref = ref_specular_exact(typed<double>(c, n));
    const double err = rel_err(k.value, ref, LD(1e-300));
    const double ad = adaptive(c, 1e-12, n);
    const double vs_adaptive = rel_err(k.value, LD(ad), LD(1e-300));
    INFO(c.name, " m=", m, ": closed ", k.value, ", reference ", double(ref), ", adaptive ", ad, ", rel.err ", err,
         ", condition ", k.condition);
    CHECK(err <= kOrdinaryBar);
    CHECK(vs_adaptive <= 1e-10);  // the adaptive form at tolerance 1e-12
    if (err > worst) { worst = err; worst_where = c.name + " m=" + fmt(m); }
    worst_vs_adaptive = std::max(worst_vs_adaptive, vs_adaptive);
    CHECK(err <= 2 * k.condition + 1e-15);  // the estimate bounds the error (measured ratio <= 0.71)
    if (k.condition > 0) worst_ratio = std::max(worst_ratio, err / k.condition);
  }
  MESSAGE("closed-form linear specular, falloff n=", n, ", random: accepted ", accepted, " of ", total,
          ", max rel.err vs reference ", worst, " (", worst_where, "), max vs adaptive ", worst_vs_adaptive,
          ", max error / condition estimate ", worst_ratio);
  CHECK(accepted >= total / 4);  // the closed form is the common case, not the exception
  }
}

TEST_CASE("closed-form linear specular: random configurations with m in [1e3, 1e4]") {
  // The stiff range of m: the integrand's own conditioning is m eps; the bar is the stiff one.
  for (const int n : kFalloffs) {
  int accepted = 0;
  double worst = 0, worst_ratio = 0;
  for (uint64_t seed = 5001; seed <= 5400; ++seed) {
    Config c = random_config(seed);
    c.shininess = std::round(std::pow(10.0, 3 + (c.shininess > 1 ? std::log10(c.shininess) / 3 : 0)));
    const int m = int(c.shininess);
    const LinearSpecularClosed<double> k = closed(c, m, n);
    CHECK(std::isfinite(k.value));
    if (!k.accepted) continue;
    ++accepted;
    const LD ref = ref_specular_exact(typed<double>(c, n));
    const double err = rel_err(k.value, ref, LD(1e-300));
    INFO(c.name, " m=", m, ": closed ", k.value, ", reference ", double(ref), ", rel.err ", err, ", condition ",
         k.condition);
    CHECK(err <= kStiffBar);
    CHECK(err <= 2 * k.condition + 1e-15);
    worst = std::max(worst, err);
    if (k.condition > 0) worst_ratio = std::max(worst_ratio, err / k.condition);
  }
  MESSAGE("closed-form linear specular, falloff n=", n, ", random m in [1e3, 1e4]: accepted ", accepted,
          " of 400, max rel.err ", worst, ", max error / condition estimate ", worst_ratio);
  CHECK(accepted > 0);
  }
}

TEST_CASE("closed-form linear specular: where the recurrence loses digits it is refused") {
  // P at the origin, N = +z, a unit segment along x at height 1, Rv in the x-z plane.
  for (const int n : kFalloffs) {
  Config c;
  c.p = {0, 0, 0};
  c.n = {0, 0, 1};
  c.q0 = {-0.5, 0, 1};
  c.q1 = {0.5, 0, 1};
  {  // lobe axis inside the segment: accepted up to m = 1e4, error ~ m eps
    for (double m : {1.0, 2.0, 3.0, 10.0, 101.0, 1000.0, 10000.0}) {
      c.rv = normalize(Vec3d{0.1, 0, 1});
      c.shininess = m;
      const LinearSpecularClosed<double> k = closed(c, int(m), n);
      const LD ref = ref_specular_exact(typed<double>(c, n));
      const double err = rel_err(k.value, ref, LD(1e-300));
      INFO("n=", n, " m=", m, ": closed ", k.value, ", reference ", double(ref), ", rel.err ", err, ", condition ", k.condition);
      CHECK(k.accepted);
      CHECK(err <= kOrdinaryBar);
      MESSAGE("lobe inside, n=", n, " m=", m, ": rel.err ", err, ", condition estimate ", k.condition);
    }
  }
  {  // lobe axis outside the segment (a highlight that misses the light): refused, and wrong if forced
    // The axis meets the line at x = 0.75, 0.25 beyond the end: the integrand is a tail ~ c_max^m.
    c.rv = normalize(Vec3d{0.75, 0, 1});
    bool seen_wrong = false;
    for (double m : {300.0, 1000.0, 3000.0}) {
      c.shininess = m;
      const LinearSpecularClosed<double> k = closed(c, int(m), n);
      const LD ref = ref_specular_exact(typed<double>(c, n));
      const double err = rel_err(k.value, ref, LD(1e-300));
      INFO("m=", m, ": forced closed ", k.value, ", reference ", double(ref), ", rel.err ", err, ", condition ",
           k.condition);
      CHECK_FALSE(k.accepted);
      if (err > 1e-6) seen_wrong = true;
      MESSAGE("lobe outside, n=", n, " m=", m, ": forced closed rel.err ", err, ", condition estimate ", k.condition,
              " (refused)");
      // `--specular exact` is right there: it takes the adaptive form.
      const Typed<double> x = typed<double>(c, n);
      const double e = shade_linear(x.light, x.sp, SpecularOptions{SpecularMethod::kExact}).specular;
      CHECK(rel_err(e, ref, LD(1e-300)) <= 1e-8);
    }
    CHECK(seen_wrong);  // the refusal is needed: the forced recurrence is wrong somewhere here
  }
  {  // a far light (short angular interval): the brackets cancel, refused at large m
    c.q0 = {1e4 - 0.5, 0, 1e4};
    c.q1 = {1e4 + 0.5, 0, 1e4};
    c.rv = normalize(Vec3d{1, 0, 1});
    c.shininess = 1000;
    const LinearSpecularClosed<double> k = closed(c, 1000, n);
    const LD ref = ref_specular_exact(typed<double>(c, n));
    MESSAGE("far 1e4, n=", n, " m=1000: forced closed rel.err ", rel_err(k.value, ref, LD(1e-300)), ", condition estimate ",
            k.condition, std::string(k.accepted ? " (accepted)" : " (refused)"));
    CHECK_FALSE(k.accepted);
  }
  }
}

TEST_CASE("closed-form linear specular: named stiff cases through --specular exact") {
  for (const int n : kFalloffs) {
  auto run = [n](const Config& c) {
    const Typed<double> x = typed<double>(c, n);
    const double e = shade_linear(x.light, x.sp, SpecularOptions{SpecularMethod::kExact}).specular;
    // P on the segment with a falloff: the integral diverges at P, defined as 0 (as the diffuse).
    const LD ref = c.name == "P on the segment" && n >= 1 ? LD(0) : ref_specular_exact(x);
    const double err = rel_err(e, ref, LD(1e-300));
    const LinearSpecularClosed<double> k = closed(c, int(c.shininess), n);
    INFO(c.name, " n=", n, " m=", c.shininess, ": exact ", e, ", reference ", double(ref), ", rel.err ", err);
    CHECK(std::isfinite(e));
    CHECK(err <= kStiffBar);
    if (k.accepted && c.shininess == std::floor(c.shininess)) {
      const double closed_err = rel_err(k.value, ref, LD(1e-300));
      CHECK(closed_err <= kStiffBar);
      // The estimate holds on the stiff cases too (the point-form special cases carry none: 0).
      if (k.condition > 0) CHECK(closed_err <= 2 * k.condition + 1e-15);
    }
    MESSAGE("stiff '", c.name, "' n=", n, " m=", c.shininess, ": rel.err ", err, std::string(k.accepted ? " (closed form)" : " (adaptive)"),
            ", closed-form condition ", k.condition);
  };
  for (const std::string& name : stiff_names()) {
    for (double m : {0.0, 1e-12, 1.0, 40.0, 1e4}) {
      Config c = stiff_case(name);
      c.shininess = m;
      run(c);
    }
  }
  // Tiny and huge lights (length 1e-6 and 1e6 of the distance), Rv toward their middle.
  for (double len : {1e-6, 1e6}) {
    for (double m : {0.0, 1e-12, 1.0, 40.0, 1e4}) run(sized_light_case(len, m));
  }
  }
}

TEST_CASE("--specular exact-no-falloff: the paper's integral without 1/|L|^n, by name") {
  // An inverse-square light (n = 2) evaluated without the falloff on its specular equals the
  // reference integrand without 1/|L|^n, and differs from the default where |L| is not ~1.
  double worst = 0;
  int differ = 0;
  for (uint64_t seed = 9001; seed <= 9200; ++seed) {
    Config c = random_config(seed);
    const Typed<double> x = typed<double>(c, 2);
    SpecularOptions paper{SpecularMethod::kExact};
    paper.falloff = SpecularFalloff::kNone;
    const double e = shade_linear(x.light, x.sp, paper).specular;
    const double with = shade_linear(x.light, x.sp, SpecularOptions{SpecularMethod::kExact}).specular;
    const LD ref = ref_specular_exact(x, false);
    const double err = rel_err(e, ref, LD(1e-300));
    INFO(c.name, " m=", c.shininess, ": no-falloff ", e, ", reference ", double(ref), ", rel.err ", err);
    CHECK(std::isfinite(e));
    CHECK(err <= 1e-8);  // real m: the adaptive form at its default tolerance 1e-9
    worst = std::max(worst, err);
    if (rel_err(with, LD(e), LD(1e-300)) > 1e-3) ++differ;
  }
  MESSAGE("exact-no-falloff, 200 random cases: max rel.err ", worst, "; differs from the default in ", differ);
  CHECK(differ > 100);
}
