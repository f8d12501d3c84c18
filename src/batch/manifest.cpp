#include "batch/manifest.h"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <set>

#include <fcntl.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "batch/shard.h"
#include "core/input_error.h"

namespace vlit {

std::string manifest_line(const ManifestRecord& r) {
  nlohmann::ordered_json j;
  j["input"] = r.input;
  j["key"] = r.key;
  j["output"] = r.output;
  j["shard"] = r.shard;
  j["status"] = r.status;
  j["vertices"] = r.vertices;
  j["seconds"] = r.seconds;
  j["error"] = r.error.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.error);
  j["time"] = r.time;
  // Paths that are not valid UTF-8 are written with replacement characters rather than refused.
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

ManifestRecord parse_manifest_line(const std::string& line, const std::string& file, std::size_t line_number) {
  const std::string where = "line " + std::to_string(line_number);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(line);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file, std::string("not JSON: ") + e.what(), where);
  }
  if (!j.is_object()) throw InputError(file, "expected one JSON object per line", where);
  auto text = [&](const char* name, bool required) -> std::string {
    const auto it = j.find(name);
    if (it == j.end() || it->is_null()) {
      if (required) throw InputError(file, std::string("missing \"") + name + "\"", where);
      return {};
    }
    if (!it->is_string()) throw InputError(file, std::string("\"") + name + "\" is not a string", where);
    return it->get<std::string>();
  };
  ManifestRecord r;
  r.input = text("input", true);
  r.status = text("status", true);
  r.key = text("key", false);
  r.output = text("output", false);
  r.shard = text("shard", false);
  r.error = text("error", false);
  r.time = text("time", false);
  if (const auto it = j.find("vertices"); it != j.end() && !it->is_null()) {
    if (!it->is_number_unsigned()) throw InputError(file, "\"vertices\" is not a whole number >= 0", where);
    r.vertices = it->get<std::size_t>();
  }
  if (const auto it = j.find("seconds"); it != j.end() && !it->is_null()) {
    if (!it->is_number()) throw InputError(file, "\"seconds\" is not a number", where);
    r.seconds = it->get<double>();
  }
  return r;
}

std::vector<ManifestRecord> read_manifest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the manifest");
  std::vector<ManifestRecord> records;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    records.push_back(parse_manifest_line(line, path, number));
  }
  return records;
}

std::string utc_timestamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm utc{};
  ::gmtime_r(&seconds, &utc);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday,
                utc.tm_hour, utc.tm_min, utc.tm_sec, static_cast<int>(ms));
  return buf;
}

ManifestWriter::ManifestWriter(const std::string& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(path, std::string("cannot open the manifest for appending: ") + std::strerror(errno));
}

ManifestWriter::~ManifestWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void ManifestWriter::append(const ManifestRecord& record) {
  const std::string line = manifest_line(record) + "\n";
  std::size_t written = 0;
  while (written < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + written, line.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(path_, std::string("cannot append to the manifest: ") + std::strerror(errno));
    }
    written += static_cast<std::size_t>(n);
  }
}

ManifestSummary summarize_manifests(const std::vector<ManifestRecord>& records) {
  ManifestSummary s;
  s.records = records.size();
  std::map<std::string, const ManifestRecord*> latest;
  std::map<std::string, std::size_t> baked;
  std::vector<std::string> order;  // keys in order of first appearance
  for (const ManifestRecord& r : records) {
    const std::string& key = r.key.empty() ? r.input : r.key;
    auto [it, inserted] = latest.emplace(key, &r);
    if (inserted) order.push_back(key);
    else if (!(r.time < it->second->time)) it->second = &r;
    if (r.status == "baked") ++baked[key];
    s.seconds += r.seconds;
    if (!s.slowest || r.seconds > s.slowest->seconds) s.slowest = r;
    if (!r.shard.empty()) ++s.shards[r.shard];
  }
  s.inputs = latest.size();
  for (const std::string& key : order) {
    const ManifestRecord& r = *latest.at(key);
    ++s.final_status[r.status];
    if (r.status == "baked") s.vertices += r.vertices;
    else if (r.status != "skipped") s.not_done.push_back(r);
    if (baked[key] > 1) s.baked_more_than_once.emplace_back(key, baked[key]);
  }
  return s;
}

std::string describe(const ManifestSummary& s) {
  std::string out = std::to_string(s.inputs) + " inputs in " + std::to_string(s.records) + " records";
  if (!s.shards.empty()) {
    out += "; shards";
    for (const auto& [shard, n] : s.shards) out += " " + shard;
    // Shards of one count N that never wrote a line: they had no input, or did not run.
    std::set<std::size_t> counts, seen;
    for (const auto& [text, n] : s.shards) {
      try {
        const Shard shard = parse_shard(text);
        counts.insert(shard.count);
        seen.insert(shard.index);
      } catch (const InputError&) {
        counts.insert(0);
      }
    }
    if (counts.size() == 1 && *counts.begin() > 0 && seen.size() < *counts.begin()) {
      out += " (no line from";
      for (std::size_t i = 0; i < *counts.begin(); ++i)
        if (!seen.count(i)) {
          out += " ";
          out += Shard{i, *counts.begin()}.text();
        }
      out += ": no input, or not run)";
    }
  }
  out += "\n";
  bool first = true;
  for (const char* status : {"baked", "skipped", "failed", "interrupted"}) {
    const auto it = s.final_status.find(status);
    // Appended piece by piece: GCC 12 gives a false -Wrestrict warning for a chain of string +.
    if (!first) out += ", ";
    out += status;
    out += " ";
    out += std::to_string(it == s.final_status.end() ? 0 : it->second);
    first = false;
  }
  for (const auto& [status, n] : s.final_status)
    if (status != "baked" && status != "skipped" && status != "failed" && status != "interrupted")
      out += ", " + status + " " + std::to_string(n);
  out += "\n";
  char buf[96];
  std::snprintf(buf, sizeof buf, "%zu vertices baked; %.2f s of bake time in all records", s.vertices, s.seconds);
  out += buf;
  if (s.slowest && s.slowest->seconds > 0) {
    std::snprintf(buf, sizeof buf, "; slowest %.2f s: ", s.slowest->seconds);
    out += buf + s.slowest->input;
  }
  out += "\n";
  if (!s.baked_more_than_once.empty()) {
    out += "baked more than once: " + std::to_string(s.baked_more_than_once.size()) + " input(s):";
    for (std::size_t i = 0; i < s.baked_more_than_once.size() && i < 10; ++i)
      out += " " + s.baked_more_than_once[i].first + " (" + std::to_string(s.baked_more_than_once[i].second) + " times)";
    if (s.baked_more_than_once.size() > 10) out += " ...";
    out += "\n";
  }
  for (const ManifestRecord& r : s.not_done)
    out += r.status + ": " + r.input + (r.error.empty() ? "" : ": " + r.error) + "\n";
  return out;
}

}  // namespace vlit
