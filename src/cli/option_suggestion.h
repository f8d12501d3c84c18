// "did you mean --lights?": the known name closest to a mistyped option or command, by edit
// distance (Levenshtein: insertions, deletions and substitutions of one character each, plus the
// swap of two neighbouring characters, Damerau's transposition).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace vlit::cli {

// The candidate nearest to `typed`, or empty when none is near enough: at most 1 edit for names
// of up to 4 characters, 2 up to 8, 3 beyond (the option's leading dashes do not count). Ties go
// to the first candidate.
std::string closest_name(const std::string& typed, const std::vector<std::string>& candidates);

// After CLI::ExtrasError: " (did you mean --lights?)" for the first unexpected argument that is
// near an option of the command being parsed (or, before any command, near a command's name);
// empty when none is.
std::string did_you_mean(const CLI::App& app);

// " (did you mean bake?)" when `typed` is near the name of one of app's commands; empty otherwise.
std::string did_you_mean_command(const CLI::App& app, const std::string& typed);

}  // namespace vlit::cli
