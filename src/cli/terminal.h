// Messages and progress on the terminal: warnings and errors go to stderr, one line each;
// progress is drawn on stderr only when it is a terminal and not silenced (--quiet), so logs and
// pipes never receive carriage returns.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace vlit::cli {

void print_warning(const std::string& line);
void print_error(const std::string& line);

bool stderr_is_terminal();

// Progress of one file: "lighting FILE  45%  1.20 M vertices/s  ETA 3 s" (bake/progress_line.h).
class Progress {
 public:
  Progress(std::string label, bool enabled);
  // Redraws at most ten times a second.
  void update(std::size_t done, std::size_t total);
  void finish();  // ends the line if one was drawn

 private:
  friend class BatchProgress;
  bool due(bool last);
  void draw(const std::string& line);
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::size_t width_ = 0;  // characters of the last line drawn, to blank a shorter one
  std::chrono::steady_clock::time_point start_, last_;
};

// Progress of a batch, one line for all files: "baking 3/10 files  NAME 40%  0.52 files/s  ETA 13 s".
class BatchProgress {
 public:
  BatchProgress(std::size_t files, bool enabled);
  void start_file(const std::string& name);         // the file now being baked
  void update_file(std::size_t done, std::size_t total);  // its vertices lit so far
  void finish_file();                                // it is done (baked or failed)
  void clear();                                      // ends the line before a message is printed

 private:
  void draw(bool force);
  Progress line_;
  std::size_t files_, files_done_ = 0;
  std::string current_;
  double fraction_ = 0;
};

}  // namespace vlit::cli
