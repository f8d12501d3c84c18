#include "cli/terminal.h"

#include <cstdio>
#include <iostream>

#include <unistd.h>

namespace vlit::cli {

void print_warning(const std::string& line) { std::cerr << "warning: " << line << "\n"; }
void print_error(const std::string& line) { std::cerr << "error: " << line << "\n"; }

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled && stderr_is_terminal()),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

void Progress::update(std::size_t done, std::size_t total) {
  if (!enabled_ || total == 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100) && done < total) return;
  last_ = now;
  drawn_ = true;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  const double rate = seconds > 0 ? done / seconds : 0;
  const double eta = rate > 0 ? (total - done) / rate : 0;
  std::fprintf(stderr, "\r%s %3.0f%%  %.2f M/s  ETA %.0f s   ", label_.c_str(), 100.0 * done / total, rate / 1e6, eta);
  std::fflush(stderr);
}

void Progress::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace vlit::cli
