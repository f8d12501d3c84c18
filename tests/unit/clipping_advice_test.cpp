// The clipping warning of a bake: when it speaks, and the exposures it advises.
#include <doctest/doctest.h>

#include "bake/clipping_advice.h"

using namespace vlit;

TEST_CASE("exposures are rounded down to 3 significant digits, so that they still fit") {
  CHECK(round_down_significant(0.012345, 3) == doctest::Approx(0.0123).epsilon(1e-12));
  CHECK(round_down_significant(1.0 / 3.0, 3) == doctest::Approx(0.333).epsilon(1e-12));
  CHECK(round_down_significant(0.9999999, 3) == doctest::Approx(0.999).epsilon(1e-12));
  CHECK(round_down_significant(123456.0, 3) == doctest::Approx(123000.0).epsilon(1e-12));
  for (double v : {0.1, 0.125, 1.0, 7.77, 1e-7, 3e12}) CHECK(round_down_significant(v, 3) <= v);
}

TEST_CASE("more than 2 % of the vertices clipped earns the advice, at most 2 % none") {
  BakeReport r;
  r.vertices = 100;
  r.clipped_vertices = 2;
  r.brightest_channel = 8;
  r.brightest_channel_p99 = 3;
  CHECK(clipping_advice(r, 1).empty());
  r.clipped_vertices = 3;
  CHECK(clipping_advice(r, 1) == "3 of 100 vertices (3.0 %) clipped above 1 at exposure 1; --exposure 0.125 fits them all, "
                                 "0.333 fits 99 %");
  // Brightest channels are measured after the exposure: at exposure 2 the advice is twice as large.
  CHECK(clipping_advice(r, 2).find("--exposure 0.25 fits them all, 0.666 fits 99 %") != std::string::npos);
  r.brightest_channel_p99 = 0.9;  // 99 % already fit: only the advice for all of them
  CHECK(clipping_advice(r, 1) == "3 of 100 vertices (3.0 %) clipped above 1 at exposure 1; --exposure 0.125 fits them all");
}
