#include "log_info.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <variant>

#include "log/carmen_log_reader.hpp"
#include "log/log_clock_reader.hpp"
#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::plog {
namespace {

// Counts per stream, the span and the largest gaps, line by line.
class Tally {
 public:
  explicit Tally(LogSummary& summary) : summary_(summary) {}

  void add(const std::string& stream, double time, bool timed) {
    auto& s = summary_.streams[stream];
    if (s.count == 0) s.first = time;
    s.last = time;
    ++s.count;
    if (!timed) return;
    ++summary_.messages;
    if (!summary_.start) summary_.start = time;
    // Gaps run from the latest time so far: a line that goes back in time
    // (the Radish logs' corrected poses at time 0) is counted, not a gap.
    if (summary_.end && time < *summary_.end) {
      ++summary_.out_of_order;
      return;
    }
    if (summary_.end) keep_gap(time - *summary_.end, *summary_.end - *summary_.start);
    summary_.end = time;
  }

 private:
  void keep_gap(double seconds, double after) {
    auto& gaps = summary_.largest_gaps;
    if (gaps.size() == LogSummary::kKeptGaps && seconds <= gaps.back().seconds) return;
    const auto at = std::upper_bound(gaps.begin(), gaps.end(), seconds,
                                     [](double s, const Gap& gap) { return s > gap.seconds; });
    gaps.insert(at, Gap{seconds, after});
    if (gaps.size() > LogSummary::kKeptGaps) gaps.pop_back();
  }

  LogSummary& summary_;
};

std::string format_number(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

std::optional<double> StreamSummary::rate() const {
  if (!rated || count < 2 || last <= first) return std::nullopt;
  const double rate = static_cast<double>(count - 1) / (last - first);
  if (rate > log::LogClock::kMaxRateHz) return std::nullopt;  // not a rate: times the clock kept anyway
  return rate;
}

LogSummary summarize_log(const std::filesystem::path& path, bool strict, Progress& progress) {
  LogSummary summary;
  summary.file = path.string();
  summary.format = detect_log_format(path);
  const auto clock = log::audit_log_times(path);
  summary.time_repair = clock->repair();
  summary.unusable_times = clock->unusable();
  summary.time_note = clock->describe();
  auto in = log::open_log_input(path);
  Tally tally(summary);
  if (summary.format == LogFormat::kPlayer) {
    log::TextLogReader reader(*in, path.string(), {.strict = strict, .clock = clock});
    while (auto line = reader.next()) {
      progress.tick();
      if (const auto* data = std::get_if<log::DataLine>(&*line)) {
        const std::string name = data->device ? protocol::to_string(*data->device)
                                              : data->interface_name + ":" + std::to_string(data->index);
        tally.add(name, data->server_time.seconds(), true);
      } else {
        tally.add("sync", std::get<log::SyncLine>(*line).server_time.seconds(), false);
      }
    }
    summary.version = std::string(log::to_string(reader.format_version()));
    summary.malformed = reader.malformed_count();
    summary.malformed_texts = reader.malformed_lines();
  } else {
    log::CarmenLogReader reader(*in, path.string(), {.strict = strict, .clock = clock});
    while (auto record = reader.next()) {
      progress.tick();
      const auto stamp = std::visit([](const auto& r) { return r.stamp; }, *record);
      std::string keyword;
      if (std::holds_alternative<log::CarmenParam>(*record)) keyword = "PARAM";
      else if (std::holds_alternative<log::CarmenOdometry>(*record)) keyword = "ODOM";
      else if (std::holds_alternative<log::CarmenTruePos>(*record)) keyword = "TRUEPOS";
      else keyword = std::string(log::carmen_laser_keyword(std::get<log::CarmenLaser>(*record).kind));
      tally.add(keyword, stamp.logger_timestamp, keyword != "PARAM");
    }
    if (auto param = summary.streams.find("PARAM"); param != summary.streams.end()) param->second.rated = false;
    summary.unknown = reader.unknown_keywords();
    summary.malformed = reader.malformed_lines();
    summary.malformed_texts = reader.malformed_messages();
  }
  if (const auto error = in->error()) throw std::runtime_error(path.string() + ": " + *error);
  return summary;
}

void print_summary(const LogSummary& summary, std::ostream& out) {
  out << "file:      " << summary.file << "\n";
  out << "format:    " << (summary.format == LogFormat::kPlayer ? "Player " + summary.version : "CARMEN") << "\n";
  if (summary.start) {
    out << "span:      " << format_number("%.6f", *summary.start) << " .. " << format_number("%.6f", *summary.end)
        << " (" << format_number("%.3f", *summary.end - *summary.start) << " s)\n";
  } else {
    out << "span:      (no messages)\n";
  }
  // "... using file order with a synthetic 10 Hz clock" or "... interpolating ...".
  if (!summary.time_note.empty()) out << "times:     " << summary.time_note << "\n";
  out << "messages:  " << summary.messages << "\n";
  out << (summary.format == LogFormat::kPlayer ? "devices:\n" : "records:\n");
  for (const auto& [name, stream] : summary.streams) {
    char line[160];
    const auto rate = stream.rate();
    std::snprintf(line, sizeof line, "  %-14s %8zu", name.c_str(), stream.count);
    out << line;
    if (rate) out << format_number("  %.3f Hz", *rate);
    out << "\n";
  }
  for (const auto& [keyword, count] : summary.unknown) out << "skipped:   " << keyword << " " << count << "\n";
  if (!summary.largest_gaps.empty()) {
    out << "gaps:     ";
    for (const auto& gap : summary.largest_gaps) {
      out << format_number(" %.3f s", gap.seconds) << format_number(" at +%.3f s;", gap.after);
    }
    out << "\n";
  }
  out << "backwards: " << summary.out_of_order << " (lines earlier than one before them)\n";
  out << "malformed: " << summary.malformed << "\n";
}

nlohmann::json summary_json(const LogSummary& summary) {
  nlohmann::json json;
  json["file"] = summary.file;
  json["format"] = std::string(log::to_string(summary.format));
  if (!summary.version.empty()) json["version"] = summary.version;
  json["messages"] = summary.messages;
  json["start"] = summary.start ? nlohmann::json(*summary.start) : nlohmann::json();
  json["end"] = summary.end ? nlohmann::json(*summary.end) : nlohmann::json();
  json["duration"] = summary.start ? nlohmann::json(*summary.end - *summary.start) : nlohmann::json();
  const char* repair = summary.time_repair == log::LogTimeRepair::kSynthetic      ? "synthetic"
                       : summary.time_repair == log::LogTimeRepair::kInterpolated ? "interpolated"
                                                                                  : "none";
  json["times"] = {{"repair", repair},
                   {"unusable", summary.unusable_times},
                   {"synthetic_rate_hz", summary.time_repair == log::LogTimeRepair::kSynthetic
                                             ? nlohmann::json(log::LogClock::kSyntheticRateHz)
                                             : nlohmann::json()},
                   {"note", summary.time_note}};
  auto& streams = json[summary.format == LogFormat::kPlayer ? "devices" : "records"];
  streams = nlohmann::json::object();
  for (const auto& [name, stream] : summary.streams) {
    const auto rate = stream.rate();
    streams[name] = {{"count", stream.count},
                     {"first", stream.first},
                     {"last", stream.last},
                     {"rate_hz", rate ? nlohmann::json(*rate) : nlohmann::json()}};
  }
  json["skipped"] = summary.unknown;
  json["gaps"] = nlohmann::json::array();
  for (const auto& gap : summary.largest_gaps) json["gaps"].push_back({{"seconds", gap.seconds}, {"after", gap.after}});
  json["out_of_order"] = summary.out_of_order;
  json["malformed"] = summary.malformed;
  json["malformed_lines"] = summary.malformed_texts;
  return json;
}

}  // namespace playerkit::plog
