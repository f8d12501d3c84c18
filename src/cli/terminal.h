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
// Columns of the terminal on stderr (TIOCGWINSZ, else $COLUMNS, else 80).
std::size_t terminal_columns();

// Progress of one file: "lighting FILE  45%  1.20 M vertices/s  ETA 3 s" (bake/progress_line.h).
// The line fits the terminal's width (FILE is shortened from the left). Whether drawn or not
// (--quiet, not a terminal), a bake whose time left is long gets one warning line
// (bake/progress_line.h, long_bake_warning).
class Progress {
 public:
  Progress(const std::string& verb, std::string name, bool enabled);
  // Redraws at most ten times a second.
  void update(std::size_t done, std::size_t total);
  void finish();  // ends the line if one was drawn

 private:
  friend class BatchProgress;
  bool due(bool last);
  void draw(const std::string& line, const std::string& name);
  // Prints the long-bake warning once, if due.
  void warn_if_long(const std::string& name, double done, double total, double seconds);
  std::string label_, name_;
  bool enabled_;
  bool warned_ = false;
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
  std::chrono::steady_clock::time_point file_start_;
};

}  // namespace vlit::cli
