// Messages and progress on the terminal: warnings and errors go to stderr, one line each;
// progress is drawn on stderr only when it is a terminal and not silenced.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace vlit::cli {

void print_warning(const std::string& line);
void print_error(const std::string& line);

class Progress {
 public:
  Progress(std::string label, bool enabled);
  // Redraws at most ten times a second: "label  45%  1.2 M/s  ETA 3 s".
  void update(std::size_t done, std::size_t total);
  void finish();

 private:
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

bool stderr_is_terminal();

}  // namespace vlit::cli
