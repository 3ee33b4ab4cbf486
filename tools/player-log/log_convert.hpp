#pragma once
// `player-log convert` and `player-log cut`.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "log_tool.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::plog {

enum class ConvertTarget { kPlayer, kCarmen, kJsonl, kCsv };

struct ConvertOptions {
  std::string input;
  std::string output;  // "-" = stdout
  std::optional<ConvertTarget> to;  // default: by the output's extension, else the other log format
  std::vector<protocol::DeviceAddress> devices;  // empty: all
  bool strict = false;
  bool si = false;  // jsonl/csv in metres and radians
};

// "player", "carmen", "jsonl", "csv"; throws UsageError.
ConvertTarget parse_convert_target(const std::string& text);

// Writes the output; warnings (and kept malformed lines) go to err. Throws
// std::runtime_error / log::LogParseError for the caller to report (exit 1).
void run_convert(const ConvertOptions& options, std::ostream& out, std::ostream& err, Progress& progress);

struct CutOptions {
  std::string input;
  std::string output;
  std::optional<double> start;  // s after the log's first time
  std::optional<double> end;
  std::vector<protocol::DeviceAddress> devices;
  bool strict = false;
};

// Copies the Player log lines inside the window (byte for byte, header too).
void run_cut(const CutOptions& options, std::ostream& out, std::ostream& err, Progress& progress);

}  // namespace playerkit::plog
