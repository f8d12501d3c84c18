// The tables and named values of a report section (report_values.h).
#include "report_values.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "report_format.h"

namespace vlit::bench::accuracy {
namespace {

const char* const kStats[] = {"d.med", "d.p99", "d.max", "d.ns", "f.med", "f.p99", "f.max", "f.ns", "stiff.d", "stiff.f"};

std::string ordinary_table(const Section& sec) {
  std::ostringstream md;
  md << "| method | set | what it promises | double: median | p99 | max | ns/eval | float: median | p99 | max | ns/eval | NaN/Inf |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : sec.rows)
    md << "| " << r.method << " | " << r.set << " | " << r.promise << " | " << fmt(r.d.med) << " | " << fmt(r.d.p99)
       << " | " << fmt(r.d.max) << " | " << fmt_ns(r.d.ns) << " | " << fmt(r.f.med) << " | " << fmt(r.f.p99) << " | "
       << fmt(r.f.max) << " | " << fmt_ns(r.f.ns) << " | " << (r.d.nonfinite + r.f.nonfinite ? "**YES**" : "no") << " |\n";
  return md.str();
}

std::string stiff_table(const StiffTable& t) {
  std::ostringstream md;
  md << "| method |";
  for (const auto& c : t.case_names) md << " " << c << " |";
  md << " NaN/Inf |\n|---|";
  for (std::size_t i = 0; i < t.case_names.size(); ++i) md << "---|";
  md << "---|\n";
  for (std::size_t m = 0; m < t.methods.size(); ++m) {
    md << "| " << t.methods[m] << " |";
    for (const auto& cell : t.max_err[m]) md << " " << fmt(cell[0]) << " / " << fmt(cell[1]) << " |";
    md << " " << (t.nonfinite[m] ? "**YES**" : "no") << " |\n";
  }
  return md.str();
}

std::string stiff_cases(const StiffTable& t) {
  std::ostringstream md;
  for (std::size_t i = 0; i < t.case_names.size(); ++i)
    md << (i ? "; " : "") << "**" << t.case_names[i] << "**: " << t.case_text[i];
  return md.str();
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
  if (!f) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace

void publish_section(Values& values, const Options& o, const Section& sec) {
  const std::string table = ordinary_table(sec), stiff = stiff_table(sec.stiff);
  fs::create_directories(o.out_dir / "tables");
  write_file(o.out_dir / "tables" / (sec.key + ".md"), table);
  write_file(o.out_dir / "tables" / (sec.key + "-stiff.md"), stiff);
  values[sec.key + ":table"] = table;
  values[sec.key + ":stiff-table"] = stiff;
  values[sec.key + ":stiff-cases"] = stiff_cases(sec.stiff);
  for (const Row& r : sec.rows) {
    const std::string p = sec.key + ":" + r.key + ":";
    if (values.count(p + "d.med")) throw std::logic_error("accuracy report: two rows named " + p);
    values[p + "d.med"] = fmt(r.d.med);
    values[p + "d.p99"] = fmt(r.d.p99);
    values[p + "d.max"] = fmt(r.d.max);
    values[p + "d.ns"] = fmt_ns(r.d.ns);
    values[p + "f.med"] = fmt(r.f.med);
    values[p + "f.p99"] = fmt(r.f.p99);
    values[p + "f.max"] = fmt(r.f.max);
    values[p + "f.ns"] = fmt_ns(r.f.ns);
    values[p + "stiff.d"] = values[p + "stiff.f"] = fmt(0);
  }
  // The stiff maxima: over the method's named cases, NaN (not applicable) cells left out.
  for (std::size_t m = 0; m < sec.stiff.keys.size(); ++m)
    for (int prec : {0, 1}) {
      double top = 0;
      for (const auto& cell : sec.stiff.max_err[m])
        if (!std::isnan(cell[prec])) top = std::max(top, cell[prec]);
      values[sec.key + ":" + sec.stiff.keys[m] + (prec ? ":stiff.f" : ":stiff.d")] = fmt(top);
    }
}

void publish_alias(Values& values, const std::string& section, const std::string& row, const std::string& alias) {
  const std::string from = section + ":" + row + ":";
  for (const std::string stat : kStats) {
    const auto it = values.find(from + stat);
    values[alias + ":" + stat] = it != values.end() ? it->second : stat.rfind("stiff", 0) == 0 ? fmt(0) : "n/a";
  }
}

void write_plot(const Options& o, const Section& sec) {
  std::ofstream dat(o.out_dir / "data" / (sec.key + ".dat"));
  for (const Row& r : sec.rows) {
    if (!r.plot) continue;
    auto fl = [](double x) { return std::max(x, 1e-18); };
    dat << "\"" << r.method << "\" " << r.d.ns << " " << fl(r.d.med) << " " << fl(r.d.p99) << " " << r.f.ns << " "
        << fl(r.f.med) << " " << fl(r.f.p99) << "\n";
  }
  std::ofstream gp(o.out_dir / "data" / (sec.key + ".gp"));
  gp << "set terminal pngcairo size 1100,700 font ',10'\n"
     << "set output 'images/accuracy/" << sec.key << ".png'\n"
     << "set logscale xy\nset format y '1e%T'\nset grid\nset key bottom left\nset offsets graph 0.02, graph 0.3, graph 0.05, graph 0.05\n"
     << "set xlabel 'time per evaluation (ns, one thread, median of repetitions)'\n"
     << "set ylabel 'relative error (point: median, bar up to the 99th percentile; 0 drawn at 1e-18)'\n"
     << "set title '" << sec.title << ": error against run time (ordinary cases)'\n"
     << "plot 'data/" << sec.key << ".dat' using 2:3:3:4 with yerrorbars pt 7 lc rgb '#1f77b4' title 'double', \\\n"
     << "     '' using 5:6:6:7 with yerrorbars pt 5 lc rgb '#d62728' title 'float', \\\n"
     << "     '' using 2:3:1 with labels offset 0.8,0.6 left font ',7' notitle\n";
}

}  // namespace vlit::bench::accuracy
