// The lobe's split by a great circle (phong_lune.h) against Boost.Math's long-double regularized
// incomplete beta function on the same double inputs, and its Gamma ratio against Boost's
// tgamma_delta_ratio; the split's two sides against an independent 1D quadrature of the lobe over a
// half-space in polar coordinates about Rv.
#include <doctest/doctest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include <algorithm>
#include <cmath>

#include "phong_lune.h"
#include "support/test_rng.h"

using namespace vlit;
using namespace vlit::test;

namespace {
using LD = long double;
}  // namespace

TEST_CASE("phong lune: Gamma(q + 1/2) / Gamma(q) against Boost.Math, q in [0.5, 1e5]") {
  double worst = 0;
  for (double q = 0.5; q < 1e5; q *= 1.37) {
    const LD ref = LD(1) / boost::math::tgamma_delta_ratio(LD(q), LD(0.5));  // Gamma(q) / Gamma(q + 1/2), inverted
    const double err = double(std::fabs(LD(gamma_half_ratio(q)) / ref - 1));
    INFO("q=", q);
    CHECK(err <= 8 * std::numeric_limits<double>::epsilon());
    worst = std::max(worst, err);
  }
  MESSAGE("phong lune: Gamma ratio max rel. error ", worst);
}

TEST_CASE("phong lune: P and Q within their estimate of Boost.Math's long-double ibeta, m in [0, 2e4]") {
  Rng rng(7);
  double worst_p = 0, worst_q = 0, worst_ratio = 0, worst_estimate = 0;
  int cases = 0, tails = 0;
  for (int i = 0; i < 20000; ++i) {
    const double m = i % 10 == 0 ? 0.0 : rng.log_uniform(1e-3, 2e4);
    const double beta = rng.log_uniform(1e-9, M_PI / 2);
    const double s = std::sin(beta);
    const PhongLune<double> r = phong_lune(s, m);
    const LD z = LD(s) * LD(s), q = (LD(m) + 1) / 2;
    // Boost's complement at q = 1/2 loses digits for tiny z (docs of linear_specular_beta.h): 1 - P
    // in long double wherever P is below 1/2.
    const LD p_ref = boost::math::ibeta(LD(0.5), q, z);
    const LD q_ref = p_ref < LD(0.5) ? 1 - p_ref : boost::math::ibetac(LD(0.5), q, z);
    if (q_ref < LD(1e-290)) continue;  // the far side below what double holds
    ++cases;
    tails += q * z >= kLuneTailFrom || z >= kLuneTailFromZ;
    const double ep = p_ref > 0 ? double(std::fabs((r.p - p_ref) / p_ref)) : std::fabs(r.p);
    const double eq = double(std::fabs((r.q - q_ref) / q_ref));
    INFO("m=", m, " beta=", beta, " P=", r.p, " ref ", double(p_ref), " Q=", r.q, " ref ", double(q_ref), " estimate ",
         r.error, " steps ", r.steps);
    CHECK(std::isfinite(r.p));
    CHECK(std::isfinite(r.q));
    CHECK(ep <= r.error);
    CHECK(eq <= r.error);
    worst_p = std::max(worst_p, ep);
    worst_q = std::max(worst_q, eq);
    worst_ratio = std::max(worst_ratio, std::max(ep, eq) / r.error);
    // What the area forms use: m >= 200 within their reach (under 30 degrees there); beyond it
    // the estimate grows with the inputs' conditioning (2 q z / (1 - z) eps for z -> 1).
    if (m >= 200 && beta <= 0.6) worst_estimate = std::max(worst_estimate, r.error);
  }
  MESSAGE("phong lune: ", cases, " cases (", tails, " by the continued fraction): max rel. error P ", worst_p, ", Q ",
          worst_q, "; error / estimate <= ", worst_ratio, "; largest estimate for m >= 200, beta <= 0.6: ", worst_estimate);
  CHECK(tails > 500);
  CHECK(worst_estimate <= 2.5e-12);  // half the area forms' bound (5e-12), up to m = 2e4
}

TEST_CASE("phong lune: the two sides against a 1D quadrature of the lobe over a half-space") {
  // In polar coordinates (t, phi) about Rv, the far side of a plane at angular distance beta is
  // phi in a window of width 2 acos(min(1, tan(beta) / tan(t))) for t > beta:
  //   far = ∫_beta^{pi/2} cos^m(t) sin(t) 2 acos(tan(beta) / tan(t)) dt.
  for (const double m : {0.0, 1e-12, 1.0, 2.5, 40.0, 200.0, 1e3, 1e4}) {
    for (const double beta : {1e-6, 0.003, 0.02, 0.1, 0.5, 1.2}) {
      const LD tb = std::tan(LD(beta));
      auto f = [&](LD t) {
        const LD lobe = m == 0 ? LD(1) : std::exp(LD(m) * std::log(std::cos(t)));
        return lobe * std::sin(t) * 2 * std::acos(std::min(LD(1), tb / std::tan(t)));
      };
      // t = beta + u^2 removes acos' square-root edge at beta; panels doubling in u resolve the
      // lobe's width ~ 1 / sqrt(m).
      auto g = [&](LD u) { return f(LD(beta) + u * u) * 2 * u; };
      const LD top = std::sqrt(LD(M_PI / 2) - LD(beta));
      LD far = 0, lo = 0;
      for (LD w = LD(1e-4); lo < top; w *= 2) {
        const LD hi = std::min(w, top);
        far += boost::math::quadrature::gauss_kronrod<LD, 61>::integrate(g, lo, hi, 6, LD(1e-17));
        lo = hi;
      }
      if (far < LD(1e-290)) continue;  // below what double holds
      const PhongLune<double> r = phong_lune(std::sin(beta), m);
      const double half = M_PI / (m + 1);
      const double err = double(std::fabs((LD(half * r.q) - far) / far));
      INFO("m=", m, " beta=", beta, " far side ", half * r.q, " quadrature ", double(far));
      CHECK(err <= std::max(r.error, 1e-13));
    }
  }
}
