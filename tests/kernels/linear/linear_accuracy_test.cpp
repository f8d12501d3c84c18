// Seeded random configurations (log-uniform scales) and the named stiff cases, every linear kernel
// against the long-double Boost.Math references of linear_reference.h, in double and float.
// With -s the test prints the accuracy table of docs/linear-lights.md:
//   ./build/linear/tests/linear_light_tests -tc="accuracy table" -s
#include <doctest/doctest.h>

#include <cstdio>

#include "linear_cases.h"

using namespace vlit;
using namespace vlit::linear_test;

namespace {

constexpr int kRandomConfigs = 300;
constexpr uint64_t kFirstSeed = 20260001;

void print_table(const Table& t) {
  std::printf("\n%-28s | %-6s | %-8s | %5s | %-10s | %-10s | %s\n", "method", "type", "family", "cases", "max error",
              "bar", "worst case");
  for (const auto& [key, w] : t) {
    const std::string method = key.substr(0, key.find(" | "));
    const bool is_float = key.find("float") != std::string::npos;
    const bool stiff = key.find("stiff") != std::string::npos;
    std::printf("%-28s | %-6s | %-8s | %5d | %10.2e | %10.0e | %s (kernel %.17g, ref %.17Lg)\n", method.c_str(),
                is_float ? "float" : "double", stiff ? "stiff" : "ordinary", w.count, w.err,
                bar_for(method, is_float, stiff), w.where.c_str(), w.value, w.ref);
  }
}

}  // namespace

TEST_CASE("accuracy table") {
  Table table;
  for (int i = 0; i < kRandomConfigs; ++i) {
    const Config c = random_config(kFirstSeed + uint64_t(i));
    check_config<double>(c, false, table);
    check_config<float>(c, false, table);
  }
  for (const std::string& name : stiff_names()) {
    const Config c = stiff_case(name);
    check_config<double>(c, true, table);
    check_config<float>(c, true, table);
  }
  if (doctest::getContextOptions()->success) print_table(table);
}
