// What one report run hands to the document: for every section its tables (also written to
// DIR/tables/<section>.md and <section>-stiff.md) and, for every row, its statistics as named
// values "<section>:<row key>:<stat>" (stat: d.med d.p99 d.max d.ns f.med f.p99 f.max f.ns, and
// stiff.d stiff.f, the max over the stiff table), filled into docs/accuracy.md.in by
// fill_template.h. Also the gnuplot data and script of each section's figure.
#pragma once

#include <string>

#include "fill_template.h"
#include "report_core.h"

namespace vlit::bench::accuracy {

// Adds the section's tables and row values; throws if two rows share a key.
void publish_section(Values& values, const Options& o, const Section& sec);

// Copies the values of row `row` of section `section` under the name `alias` ("<alias>:<stat>"),
// "n/a" (stiff: "0") where the section has no such row: the document names a default's row
// without knowing the default's value.
void publish_alias(Values& values, const std::string& section, const std::string& row, const std::string& alias);

// DIR/data/<section>.dat and .gp: error against time, double and float, of the plotted rows.
void write_plot(const Options& o, const Section& sec);

}  // namespace vlit::bench::accuracy
