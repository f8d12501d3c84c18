// The incomplete-beta form of the linear specular with falloff n = 2 (linear_specular_beta.h)
// against the independent long-double Boost.Math quadrature (linear_reference.h, parametrised in t,
// not in the kernel's angle) and against the adaptive form in the same test: seeded random
// configurations with real m, m up to 1e4, the tails the recurrence refuses, the named stiff cases;
// its error estimate bounds its error; where it refuses, `--specular exact` is still right.
#include <doctest/doctest.h>

#include <boost/math/special_functions/beta.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "linear_cases.h"
#include "linear_specular_beta.h"

using namespace vlit;
using namespace vlit::linear_test;

namespace {

constexpr double kOrdinaryBar = 1e-12;
constexpr double kStiffBar = 1e-9;

// The beta form in world units (the frame's value times scale^-2).
LinearSpecularClosed<double> beta_form(const Config& c) {
  const Typed<double> x = typed<double>(c, 2);
  const LinearFrame<double> fr = make_linear_frame_precise(x.light, x.sp);
  LinearSpecularClosed<double> k = linear_specular_beta_frame(fr, c.shininess);
  k.value *= linear_scale_factor(fr.scale, 2);
  return k;
}

double adaptive(const Config& c, double tol) {
  const Typed<double> x = typed<double>(c, 2);
  const LinearFrame<double> fr = make_linear_frame_precise(x.light, x.sp);
  return linear_specular_exact_frame(fr, c.shininess, tol, 2.0) * linear_scale_factor(fr.scale, 2);
}

double exact_specular(const Config& c) {
  const Typed<double> x = typed<double>(c, 2);
  return shade_linear(x.light, x.sp, SpecularOptions{SpecularMethod::kExact}).specular;
}

struct Tally {
  int accepted = 0, total = 0;
  double worst = 0, worst_ratio = 0;
  std::string where;
};

// Checks one accepted case against the reference: within `bar` and within twice its estimate.
void check_accepted(const Config& c, const LinearSpecularClosed<double>& k, double bar, Tally& t) {
  const LD ref = ref_specular_exact(typed<double>(c, 2));
  const double err = rel_err(k.value, ref, LD(1e-300));
  INFO(c.name, " m=", c.shininess, ": beta form ", k.value, ", reference ", double(ref), ", rel.err ", err,
       ", condition ", k.condition);
  CHECK(err <= bar);
  CHECK(err <= 2 * k.condition + 1e-15);
  if (err > t.worst) { t.worst = err; t.where = c.name + " m=" + std::to_string(c.shininess); }
  if (k.condition > 0) t.worst_ratio = std::max(t.worst_ratio, err / k.condition);
}

}  // namespace

TEST_CASE("beta-form linear specular: the head and tail values within their charges") {
  // The kernel charges each head H(ψ) = ∫_0^ψ cos^m and tail T(ψ) = ∫_ψ^(π/2) cos^m the relative
  // error `charge` eps (Boost's double evaluation: kLinearBetaRoundoff, plus m / 2 for tails from cos²ψ).
  // Against the long-double incomplete beta
  // functions on the same arguments (sin²ψ + cos²ψ = 1 exactly in double, so that both arguments
  // describe the same ψ), each value must stay within half its charge, for m in (0, 1e4] (m = 0
  // takes W = Δθ without Boost, whose double complements at q = ½ lose up to 1e7 eps for arguments
  // below 1e-15). Values below the smallest normal double are compared absolutely.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u01(0, 1);
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double worst[2] = {0, 0};
  for (int i = 0; i < 8000; ++i) {
    const double m = i % 4 == 0 ? std::ceil(100 * u01(rng)) : std::pow(10.0, -12 + 16 * u01(rng));
    const double q = (m + 1) / 2;
    const double small = 0.5 * std::pow(10.0, -30 * u01(rng) * u01(rng));
    double s2, c2;
    if (i % 2) { c2 = 1 - small; s2 = 1 - c2; } else { s2 = 1 - small; c2 = 1 - s2; }
    const LD head_ref = LD(0.5) * boost::math::beta(LD(0.5), LD(q), LD(s2));
    const LD tail_ref = LD(0.5) * boost::math::beta(LD(q), LD(0.5), LD(c2));
    const linear_beta_detail::Charged<double> h = linear_beta_detail::head(s2, c2, q);
    const linear_beta_detail::Charged<double> t = linear_beta_detail::tail(s2, c2, q);
    const LD floor = LD(std::numeric_limits<double>::min()) / eps;
    const double eh = rel_err(h.value, head_ref, floor) / eps, et = rel_err(t.value, tail_ref, floor) / eps;
    INFO("m=", m, " sin2=", s2, " cos2=", c2, ": head ", h.value, " vs ", double(head_ref), " (", eh, " eps, charged ",
         h.charge, "), tail ", t.value, " vs ", double(tail_ref), " (", et, " eps, charged ", t.charge, ")");
    CHECK(std::isfinite(h.value));
    CHECK(std::isfinite(t.value));
    CHECK(eh <= h.charge / 2);
    CHECK(et <= t.charge / 2);
    worst[0] = std::max(worst[0], eh);
    worst[1] = std::max(worst[1], et);
  }
  MESSAGE("head values against long double: max ", worst[0], " eps; tail values: max ", worst[1], " eps");
}

TEST_CASE("beta-form linear specular: random configurations with real m vs the Boost.Math reference") {
  Tally t;
  for (uint64_t seed = 1; seed <= 2000; ++seed) {
    Config c = random_config(seed);  // real m log-uniform in [1, 1e3]
    if (seed % 5 == 0) c.shininess = std::round(c.shininess);
    const LinearSpecularClosed<double> k = beta_form(c);
    CHECK(std::isfinite(k.value));
    ++t.total;
    if (!k.accepted) continue;
    ++t.accepted;
    check_accepted(c, k, kOrdinaryBar, t);
    const double ad = adaptive(c, 1e-12);
    INFO(c.name, " m=", c.shininess, ": beta form ", k.value, ", adaptive ", ad);
    CHECK(rel_err(k.value, LD(ad), LD(1e-300)) <= 1e-10);  // the adaptive form at tolerance 1e-12
  }
  MESSAGE("beta-form linear specular, random, m in [1, 1e3]: accepted ", t.accepted, " of ", t.total,
          ", max rel.err vs reference ", t.worst, " (", t.where, "), max error / condition estimate ", t.worst_ratio);
  CHECK(t.accepted >= t.total * 8 / 10);  // the form accepts tails: refusals are the short lights
}

TEST_CASE("beta-form linear specular: random configurations with m in [1e3, 1e4]") {
  Tally t;
  for (uint64_t seed = 5001; seed <= 5400; ++seed) {
    Config c = random_config(seed);
    c.shininess = std::pow(10.0, 3 + std::log10(c.shininess) / 3);
    const LinearSpecularClosed<double> k = beta_form(c);
    CHECK(std::isfinite(k.value));
    ++t.total;
    if (!k.accepted) continue;
    ++t.accepted;
    check_accepted(c, k, kStiffBar, t);
  }
  MESSAGE("beta-form linear specular, random, m in [1e3, 1e4]: accepted ", t.accepted, " of ", t.total,
          ", max rel.err ", t.worst, " (", t.where, "), max error / condition estimate ", t.worst_ratio);
  CHECK(t.accepted >= t.total * 8 / 10);
}

TEST_CASE("beta-form linear specular: random configurations with m = 0 and m in [1e-12, 1]") {
  // Below m = 1 the lobe is nearly a step at its zero (Rv.L = 0), so the result moves with the
  // frame's rounding of that zero's position by more than the bar, the same for every method: the
  // reference check takes the stiff bar, and the estimate is checked against the adaptive form on
  // the same frame.
  Tally t;
  double worst_vs_adaptive = 0;
  for (uint64_t seed = 7001; seed <= 7400; ++seed) {
    Config c = random_config(seed);
    c.shininess = seed % 4 == 0 ? 0.0 : std::pow(10.0, -4 * std::log10(c.shininess));
    const LinearSpecularClosed<double> k = beta_form(c);
    CHECK(std::isfinite(k.value));
    ++t.total;
    if (!k.accepted) continue;
    ++t.accepted;
    const LD ref = ref_specular_exact(typed<double>(c, 2));
    const double err = rel_err(k.value, ref, LD(1e-300));
    const double ad = adaptive(c, 1e-14);
    const double vs_adaptive = rel_err(k.value, LD(ad), LD(1e-300));
    INFO(c.name, " m=", c.shininess, ": beta form ", k.value, ", reference ", double(ref), ", adaptive ", ad,
         ", condition ", k.condition);
    CHECK(err <= kStiffBar);
    CHECK(vs_adaptive <= 2 * k.condition + 1e-13);
    t.worst = std::max(t.worst, err);
    worst_vs_adaptive = std::max(worst_vs_adaptive, vs_adaptive);
  }
  MESSAGE("beta-form linear specular, random, m = 0 and m in [1e-12, 1]: accepted ", t.accepted, " of ", t.total,
          ", max rel.err vs reference ", t.worst, ", vs the adaptive form ", worst_vs_adaptive);
  CHECK(t.accepted >= t.total * 8 / 10);
}

TEST_CASE("beta-form linear specular: a highlight that misses the light, which the recurrence refuses") {
  // P at the origin, N = +z, a unit segment along x at height 1; the lobe's axis meets the line at
  // x = 0.75, 0.25 beyond the end: the integrand is a tail ~ c_max^m.
  Config c;
  c.p = {0, 0, 0};
  c.n = {0, 0, 1};
  c.q0 = {-0.5, 0, 1};
  c.q1 = {0.5, 0, 1};
  c.rv = normalize(Vec3d{0.75, 0, 1});
  Tally t;
  for (double m : {0.0, 1.0, 2.5, 40.0, 300.0, 1000.0, 3000.0, 10000.0}) {
    c.shininess = m;
    c.name = "lobe outside";
    const LinearSpecularClosed<double> k = beta_form(c);
    CHECK(k.accepted);
    check_accepted(c, k, m > 1000 ? kStiffBar : kOrdinaryBar, t);
    if (m >= 300) {
      const Typed<double> x = typed<double>(c, 2);
      CHECK_FALSE(linear_specular_closed_frame(make_linear_frame_precise(x.light, x.sp), int(m), 2).accepted);
    }
  }
  MESSAGE("lobe outside the light, m in [0, 1e4]: max rel.err ", t.worst, " (", t.where, ")");
}

TEST_CASE("beta-form linear specular: named stiff cases, and where it refuses `--specular exact` is right") {
  Tally t;
  int refused = 0;
  auto run = [&](Config c) {
    const LinearSpecularClosed<double> k = beta_form(c);
    const Typed<double> x = typed<double>(c, 2);
    const LD ref = c.name == "P on the segment" ? LD(0) : ref_specular_exact(x);
    const double e = exact_specular(c);
    INFO(c.name, " m=", c.shininess, ": beta form ", k.value, (k.accepted ? " (accepted)" : " (refused)"),
         ", --specular exact ", e, ", reference ", double(ref));
    CHECK(std::isfinite(k.value));
    CHECK(rel_err(e, ref, LD(1e-300)) <= kStiffBar);
    if (k.accepted) {
      const double err = rel_err(k.value, ref, LD(1e-300));
      CHECK(err <= kStiffBar);
      if (k.condition > 0) CHECK(err <= 2 * k.condition + 1e-15);
      t.worst = std::max(t.worst, err);
    } else {
      ++refused;
    }
  };
  for (const std::string& name : stiff_names())
    for (double m : {0.0, 1e-12, 1.0, 2.5, 40.0, 1e4}) {
      Config c = stiff_case(name);
      c.shininess = m;
      run(c);
    }
  for (double len : {1e-6, 1e6})
    for (double m : {0.0, 1e-12, 1.0, 2.5, 40.0, 1e4}) run(sized_light_case(len, m));
  MESSAGE("beta form on the named stiff cases: max rel.err where accepted ", t.worst, ", refused ", refused);
  CHECK(refused > 0);  // some of the short lights are refused
}

TEST_CASE("beta-form linear specular: a short light is refused, and `--specular exact` is right there") {
  // A light of length 1e-9 at distance ~1 with the lobe's axis on it: W ~ c^m Δψ, and the rounding
  // of ψ at each end (a few eps) is 1e-7 of Δψ: the two ends' values cannot give W.
  Config c;
  c.name = "length 1e-9";
  c.p = {0, 0, 0};
  c.n = {0, 0, 1};
  c.q0 = {0.3, 0.2, 1};
  c.q1 = {0.3 + 1e-9, 0.2 + 1e-9, 1};
  c.rv = normalize(Vec3d{0.3, 0.2, 1});
  for (double m : {1.5, 40.5, 1000.0}) {
    c.shininess = m;
    const LinearSpecularClosed<double> k = beta_form(c);
    const LD ref = ref_specular_exact(typed<double>(c, 2));
    INFO("m=", m, ": beta form ", k.value, (k.accepted ? " (accepted)" : " (refused)"), ", reference ", double(ref));
    CHECK_FALSE(k.accepted);
    CHECK(rel_err(exact_specular(c), ref, LD(1e-300)) <= 1e-8);
  }
  // Lengths from 1e-1 down to 1e-8: the form accepts the longer ones, refuses the shorter, and is
  // within the ordinary bar wherever it accepts.
  int accepted = 0, refused = 0;
  for (double len = 1e-1; len > 1e-8; len /= 3) {
    c.q1 = c.q0 + Vec3d{len, len, 0};
    c.shininess = 40.5;
    const LinearSpecularClosed<double> k = beta_form(c);
    if (!k.accepted) { ++refused; continue; }
    ++accepted;
    const LD ref = ref_specular_exact(typed<double>(c, 2));
    const double err = rel_err(k.value, ref, LD(1e-300));
    INFO("length ", len, ": beta form ", k.value, ", reference ", double(ref), ", rel.err ", err, ", condition ", k.condition);
    CHECK(err <= kOrdinaryBar);
  }
  MESSAGE("lights of length 1e-1 to 1e-8 at distance 1, m = 40.5: accepted ", accepted, ", refused ", refused);
  CHECK(accepted > 0);
  CHECK(refused > 0);
}
