// One TEST_CASE per named stiff case (docs/linear-lights.md): every kernel in double and float
// against the long-double reference, every output finite.
#include <doctest/doctest.h>

#include "linear_cases.h"

using namespace vlit;
using namespace vlit::linear_test;

namespace {
void run_stiff(const char* name) {
  Table table;
  const Config c = stiff_case(name);
  check_config<double>(c, true, table);
  check_config<float>(c, true, table);
}
}  // namespace

TEST_CASE("stiff: collinear") { run_stiff("collinear"); }
TEST_CASE("stiff: near-collinear") { run_stiff("near-collinear"); }
TEST_CASE("stiff: far 1e6") { run_stiff("far 1e6"); }
TEST_CASE("stiff: near 1e-6") { run_stiff("near 1e-6"); }
TEST_CASE("stiff: crossing horizon") { run_stiff("crossing horizon"); }
TEST_CASE("stiff: endpoint on tangent plane") { run_stiff("endpoint on tangent plane"); }
TEST_CASE("stiff: grazing normal") { run_stiff("grazing normal"); }
TEST_CASE("stiff: zero-length") { run_stiff("zero-length"); }
TEST_CASE("stiff: P on the segment") { run_stiff("P on the segment"); }
