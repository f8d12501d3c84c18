#include "cli/vector_option.h"

#include <cmath>
#include <cstdlib>

namespace vlit::cli {

CLI::Option* add_vector3_option(CLI::App& command, const std::string& name, std::vector<double>& values,
                                const std::string& description) {
  // CLI11 splits each argument at the delimiter and counts the pieces: "1,2,3" is three values,
  // as "1 2 3" is, and the option stops after three (a positional argument after it stays one).
  return command.add_option(name, values, description)
      ->expected(3)
      ->allow_extra_args(false)  // a vector option of CLI11 would otherwise take every argument up to the next option
      ->delimiter(',')
      ->type_name("X,Y,Z")
      ->check(CLI::Validator(
          [](const std::string& value) {
            char* end = nullptr;
            const double v = std::strtod(value.c_str(), &end);
            return !value.empty() && end == value.c_str() + value.size() && std::isfinite(v)
                       ? std::string()
                       : "\"" + value + "\" is not a finite number (give three, as 1,2,3 or 1 2 3)";
          },
          "NUMBER"));
}

}  // namespace vlit::cli
