#include "cli/option_suggestion.h"

#include <algorithm>

namespace vlit::cli {
namespace {

std::string without_dashes(const std::string& s) { return s.substr(std::min(s.find_first_not_of('-'), s.size())); }

// Optimal string alignment distance (Levenshtein with adjacent transpositions).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::string closest_name(const std::string& typed, const std::vector<std::string>& candidates) {
  const std::string word = without_dashes(typed);
  if (word.empty()) return {};
  const std::size_t allowed = word.size() <= 4 ? 1 : word.size() <= 8 ? 2 : 3;
  std::string best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(word, without_dashes(candidate));
    if (distance < best_distance) best_distance = distance, best = candidate;
  }
  return best;
}

std::string did_you_mean_command(const CLI::App& app, const std::string& typed) {
  std::vector<std::string> commands;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) commands.push_back(sub->get_name());
  const std::string near = closest_name(typed, commands);
  return near.empty() ? std::string() : " (did you mean " + near + "?)";
}

std::string did_you_mean(const CLI::App& app) {
  const std::vector<const CLI::App*> parsed = app.get_subcommands([](const CLI::App* sub) { return sub->parsed(); });
  const CLI::App& where = parsed.empty() ? app : *parsed.back();
  std::vector<std::string> options, commands;
  for (const CLI::Option* option : where.get_options())
    for (const std::string& name : option->get_lnames()) options.push_back("--" + name);
  if (parsed.empty())
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) commands.push_back(sub->get_name());
  for (const std::string& arg : where.remaining()) {
    const std::string name = arg.substr(0, arg.find('='));  // --lihgts=x.json
    const std::string near = closest_name(name, name.rfind("--", 0) == 0 ? options : commands);
    if (!near.empty()) return " (did you mean " + near + "?)";
  }
  return {};
}

}  // namespace vlit::cli
