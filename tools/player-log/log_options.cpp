#include "log_options.hpp"

#include <cmath>

namespace playerkit::plog {
namespace {

std::vector<protocol::DeviceAddress> devices_or_all(const std::string& text) {
  if (text.empty()) return {};
  return parse_device_list(text);
}

}  // namespace

ConvertOptions make_convert_options(const ConvertCommandLine& command_line) {
  ConvertOptions options;
  options.input = command_line.input;
  options.output = command_line.output;
  options.si = command_line.si;
  options.strict = command_line.strict;
  if (!command_line.to.empty()) options.to = parse_convert_target(command_line.to);
  options.devices = devices_or_all(command_line.devices);
  return options;
}

CutOptions make_cut_options(const CutCommandLine& command_line) {
  CutOptions options;
  options.input = command_line.input;
  options.output = command_line.output;
  options.strict = command_line.strict;
  options.devices = devices_or_all(command_line.devices);
  if (command_line.start && command_line.end && *command_line.end < *command_line.start) {
    throw UsageError("--end is before --start");
  }
  options.start = command_line.start;
  options.end = command_line.end;
  return options;
}

RecordOptions make_record_options(const RecordCommandLine& command_line) {
  RecordOptions options;
  options.output = command_line.output;
  options.strict = command_line.strict;
  options.count = command_line.count;
  parse_record_targets(command_line.targets, options);
  if (command_line.duration && !(*command_line.duration > 0)) throw UsageError("--duration must be > 0");
  if (!(command_line.timeout > 0)) throw UsageError("--timeout must be > 0");
  options.duration = command_line.duration;
  options.timeout = command_line.timeout;
  if (command_line.frequency) {
    const double hz = *command_line.frequency;
    if (!(hz >= 1 && hz <= 65535) || hz != std::floor(hz)) {
      throw UsageError("--frequency is the server's data frequency: a whole number of Hz, 1 to 65535");
    }
    if (options.from_stdin) throw UsageError("--frequency is for recording from a server, not from stdin");
    options.frequency = static_cast<std::uint16_t>(hz);
  }
  return options;
}

ReplayOptions make_replay_options(const ReplayCommandLine& command_line) {
  ReplayOptions options;
  options.input = command_line.input;
  options.port = command_line.port;
  options.bind_address = command_line.bind_address;
  options.loop = command_line.loop;
  options.burst = command_line.burst;
  options.devices = devices_or_all(command_line.devices);
  if (!(command_line.rate > 0 && command_line.rate < 1e6)) {
    throw UsageError("--rate must be above 0 and below 1000000");
  }
  if (!(command_line.start >= 0)) throw UsageError("--start must be 0 or more");
  if (command_line.duration && !(*command_line.duration > 0)) throw UsageError("--duration must be > 0");
  options.rate = command_line.rate;
  options.start = command_line.start;
  options.duration = command_line.duration;
  if (command_line.quiet) options.log_level = core::LogLevel::kError;
  return options;
}

}  // namespace playerkit::plog
