// A usage error found after the options were parsed (a --camera the file does not have): the
// command line prints it like any error and exits 2, the status of every usage error (README
// "Exit status").
#pragma once

#include <stdexcept>
#include <string>

namespace vlit::cli {

class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace vlit::cli
