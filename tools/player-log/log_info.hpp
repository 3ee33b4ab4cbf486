#pragma once
// `player-log info`: what a log holds, read once in constant memory.

#include <cstddef>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "log/log_clock.hpp"
#include "log_tool.hpp"

namespace playerkit::plog {

struct StreamSummary {
  std::size_t count = 0;
  double first = 0;  // s, the log's time (Player token 0, CARMEN logger_timestamp)
  double last = 0;
  bool rated = true;  // false for CARMEN's PARAM: configuration, not a stream
  // Messages per second over the stream's own span; nullopt under two
  // messages, for streams not rated, or for a rate no log can have.
  [[nodiscard]] std::optional<double> rate() const;
};

struct Gap {
  double seconds = 0;  // between a message and the latest time before it
  double after = 0;    // time of the first of the two, relative to the log's start
};

struct LogSummary {
  std::string file;
  LogFormat format = LogFormat::kPlayer;
  std::string version;  // "0.0.0"/"0.2.0", or "" for CARMEN
  // Player: "laser:0", ..., and "sync"; CARMEN: record keywords.
  std::map<std::string, StreamSummary> streams;
  std::map<std::string, std::size_t> unknown;  // CARMEN keywords skipped
  std::size_t messages = 0;                    // timed lines (not PARAM, not sync)
  std::optional<double> start;
  std::optional<double> end;
  std::vector<Gap> largest_gaps;  // largest first, at most kKeptGaps
  std::size_t out_of_order = 0;   // timed lines earlier than the latest time before them
  std::size_t malformed = 0;
  std::vector<std::string> malformed_texts;
  // How the log's times were judged (log/log_clock.hpp); times above are
  // the repaired ones.
  log::LogTimeRepair time_repair = log::LogTimeRepair::kNone;
  std::size_t unusable_times = 0;
  std::string time_note;  // LogClock::describe(), "" when every time was usable

  static constexpr std::size_t kKeptGaps = 5;
};

// Throws std::runtime_error (unreadable) or log::LogParseError (strict).
LogSummary summarize_log(const std::filesystem::path& path, bool strict, Progress& progress);

void print_summary(const LogSummary& summary, std::ostream& out);
nlohmann::json summary_json(const LogSummary& summary);

}  // namespace playerkit::plog
