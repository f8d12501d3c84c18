// The one syntax for a 3-vector on the command line (--specular-eye, --background): three finite
// numbers, given either as one argument with commas ("1,2,3") or as three arguments ("1 2 3").
// Anything else is a usage error naming the option.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace vlit::cli {

// `values` receives the three numbers (left as it is when the option is absent).
CLI::Option* add_vector3_option(CLI::App& command, const std::string& name, std::vector<double>& values,
                                const std::string& description);

}  // namespace vlit::cli
