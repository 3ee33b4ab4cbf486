#pragma once
// What each player-log subcommand was asked to do, checked: the flags as
// CLI11 fills them (the *CommandLine structs, plain strings and numbers)
// become the subcommand's options, or a UsageError naming the flag. Pure, so
// the rules are unit-tested (log_options_test.cpp). info takes its two flags
// as they are and has nothing to check.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "log_convert.hpp"
#include "log_record.hpp"
#include "log_replay.hpp"
#include "log_tool.hpp"

namespace playerkit::plog {

// The flags as typed; empty strings and nullopt mean "not given".
struct ConvertCommandLine {
  std::string input;
  std::string output;
  std::string to;       // player, carmen, jsonl or csv
  std::string devices;  // "laser:0,position:0"
  bool si = false;
  bool strict = false;
};

struct CutCommandLine {
  std::string input;
  std::string output;
  std::optional<double> start;
  std::optional<double> end;
  std::string devices;
  bool strict = false;
};

struct RecordCommandLine {
  std::vector<std::string> targets;  // ["-"] or [HOST[:PORT]] DEVICE...
  std::string output;
  std::optional<double> duration;
  std::optional<std::uint64_t> count;
  double timeout = RecordOptions().timeout;
  bool strict = false;
  std::optional<double> frequency;  // Hz, a whole number
};

struct ReplayCommandLine {
  std::string input;
  std::uint16_t port = ReplayOptions().port;
  std::string bind_address = ReplayOptions().bind_address;
  double rate = ReplayOptions().rate;
  bool loop = false;
  double start = 0.0;
  std::optional<double> duration;
  std::string devices;
  bool burst = false;
  bool quiet = false;
};

// Throw UsageError.
ConvertOptions make_convert_options(const ConvertCommandLine& command_line);
CutOptions make_cut_options(const CutCommandLine& command_line);
RecordOptions make_record_options(const RecordCommandLine& command_line);
ReplayOptions make_replay_options(const ReplayCommandLine& command_line);

}  // namespace playerkit::plog
