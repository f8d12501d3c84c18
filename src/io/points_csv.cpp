#include "io/points_csv.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/input_error.h"
#include "io/read_file.h"

namespace vlit {
namespace {

std::string trim(std::string s) {
  const char* ws = " \t\r";
  s.erase(0, s.find_first_not_of(ws));
  s.erase(s.find_last_not_of(ws) + 1);
  return s;
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

}  // namespace

std::vector<ProbePoint> parse_points_csv(const std::string& text, const std::string& name) {
  static const char* kColumns[] = {"px", "py", "pz", "nx", "ny", "nz", "ex", "ey", "ez", "m"};
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  bool header_seen = false;
  std::vector<ProbePoint> points;
  while (std::getline(in, line)) {
    ++line_no;
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    const std::string where = "line " + std::to_string(line_no);
    const auto fields = split_commas(line);
    if (!header_seen) {
      bool ok = fields.size() == 10;
      for (size_t i = 0; ok && i < 10; ++i) ok = fields[i] == kColumns[i];
      if (!ok) throw InputError(name, "expected the header px,py,pz,nx,ny,nz,ex,ey,ez,m", where);
      header_seen = true;
      continue;
    }
    if (fields.size() != 10)
      throw InputError(name, "expected 10 comma-separated numbers, found " + std::to_string(fields.size()), where);
    double v[10];
    for (int i = 0; i < 10; ++i) {
      const std::string& f = fields[i];
      const char* begin = f.data();
      const char* end = f.data() + f.size();
      if (begin != end && *begin == '+') ++begin;
      const auto [ptr, ec] = std::from_chars(begin, end, v[i]);
      if (ec != std::errc() || ptr != end || f.empty() || !std::isfinite(v[i]))
        throw InputError(name, std::string("column ") + kColumns[i] + ": \"" + f + "\" is not a finite number", where);
    }
    ProbePoint p{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}, v[9]};
    if (!(length_squared(p.normal) > 0)) throw InputError(name, "normal has zero length", where);
    if (p.shininess < 0) throw InputError(name, "shininess m must be >= 0", where);
    points.push_back(p);
  }
  if (!header_seen) throw InputError(name, "empty file: expected the header px,py,pz,nx,ny,nz,ex,ey,ez,m");
  return points;
}

std::vector<ProbePoint> read_points_csv(const std::string& path) {
  return parse_points_csv(read_text_file(path), path);
}

}  // namespace vlit
