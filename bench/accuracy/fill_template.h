// Fills a Markdown template with the values of one report run: the document's prose lives in
// the template (docs/accuracy.md.in), the numbers and tables come from the program.
//
//   {{name}}            the value `name`; a name without a value is an error
//   {{#name}}...{{/name}}  the text inside, if `name` has a non-empty value (blocks of different
//                          names may nest)
//   {{^name}}...{{/name}}  the text inside, if `name` has no value or an empty one
//
// Everything else is copied byte for byte.
#pragma once

#include <map>
#include <string>

namespace vlit::bench::accuracy {

using Values = std::map<std::string, std::string>;

// Throws std::runtime_error naming `template_name`, the line and the problem (unknown name,
// unclosed tag or block).
std::string fill_template(const std::string& text, const Values& values, const std::string& template_name);

}  // namespace vlit::bench::accuracy
