// The one error type for bad input: it names the file and, where known, the place in it, so the
// command line can print a single line "FILE: [where: ]problem" and exit non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace vlit {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string problem, std::string where = {})
      : std::runtime_error(format(file, problem, where)),
        file_(std::move(file)), problem_(std::move(problem)), where_(std::move(where)) {}

  const std::string& file() const { return file_; }
  const std::string& problem() const { return problem_; }
  const std::string& where() const { return where_; }

 private:
  static std::string format(const std::string& file, const std::string& problem, const std::string& where) {
    std::string s = file.empty() ? std::string("<input>") : file;
    s += ": ";
    if (!where.empty()) s += where + ": ";
    return s + problem;
  }
  std::string file_, problem_, where_;
};

}  // namespace vlit
