#include "view_options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "device_arguments.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::player_view {
namespace {

void check_seconds(const std::optional<double>& value, const std::string& flag, bool zero_allowed) {
  if (!value) return;
  const bool fine = std::isfinite(*value) && (zero_allowed ? *value >= 0.0 : *value > 0.0);
  if (!fine) throw UsageError(flag + " must be a " + (zero_allowed ? "non-negative" : "positive") + " number of seconds");
}

int parse_side(std::string_view text, const std::string& whole) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 16 || value > 8192) {
    throw UsageError("--size '" + whole + "': expected WIDTHxHEIGHT in pixels, each 16 to 8192 (e.g. 800x600)");
  }
  return value;
}

void parse_size(const std::string& text, view::RenderOptions& render) {
  const auto x = text.find('x');
  if (x == std::string::npos) parse_side("", text);
  const std::string_view all(text);
  render.width = parse_side(all.substr(0, x), text);
  render.height = parse_side(all.substr(x + 1), text);
}

double parse_coordinate(std::string_view text, const std::string& whole) {
  // The whole text must be the number: "1,2x" is refused, not read as 1, 2.
  const std::string copy(text);
  char* end = nullptr;
  const double value = std::strtod(copy.c_str(), &end);
  if (copy.empty() || end != copy.c_str() + copy.size() || !std::isfinite(value)) {
    throw UsageError("--origin: '" + whole + "' is not X,Y (two numbers in metres)");
  }
  return value;
}

void parse_map_flags(const CommandLine& command_line, ViewOptions& options) {
  if (command_line.map.empty()) {
    if (command_line.scale) throw UsageError("--scale is the map image's metres per pixel: it needs --map");
    if (command_line.negate) throw UsageError("--negate applies to a map image: it needs --map");
    if (command_line.origin) throw UsageError("--origin places a map image: it needs --map");
    return;
  }
  options.map = command_line.map;
  if (command_line.scale && !(std::isfinite(*command_line.scale) && *command_line.scale > 0)) {
    throw UsageError("--scale must be a positive number of metres per pixel");
  }
  options.map_loading.resolution = command_line.scale;
  options.map_loading.negate = command_line.negate;
  if (command_line.origin) {
    const std::string& text = *command_line.origin;
    const auto comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
      throw UsageError("--origin: '" + text + "' is not X,Y (two numbers in metres)");
    }
    const std::string_view all(text);
    options.map_loading.origin =
        Eigen::Vector2d(parse_coordinate(all.substr(0, comma), text), parse_coordinate(all.substr(comma + 1), text));
  }
}

void parse_http(const CommandLine& command_line, ViewOptions& options) {
  if (command_line.after) throw UsageError("--after applies to --snapshot, not to the live page");
  if (command_line.every || command_line.count) throw UsageError("--every and --count apply to --record, not to the live page");
  options.output = Output::kHttp;
  options.http_port = *command_line.http;
  options.drive = command_line.drive;
  if (!std::isfinite(command_line.speed) || command_line.speed <= 0.0 || command_line.speed > 10.0) {
    throw UsageError("--speed must be more than 0 and at most 10 m/s");
  }
  if (!std::isfinite(command_line.turn) || command_line.turn <= 0.0 || command_line.turn > 360.0) {
    throw UsageError("--turn must be more than 0 and at most 360 degrees/s");
  }
  options.speed = command_line.speed;
  options.turn_rate = command_line.turn * std::numbers::pi / 180.0;
  if (!command_line.bind.empty()) options.bind = command_line.bind;
}

void parse_output(const CommandLine& command_line, ViewOptions& options) {
  const bool snapshot = !command_line.snapshot.empty(), record = !command_line.record.empty();
  const bool http = command_line.http.has_value();
  if (int(snapshot) + int(record) + int(http) > 1) {
    throw UsageError("--snapshot, --record and --http: choose one");
  }
  if (!snapshot && !record && !http) {
    throw UsageError(
        "say what to make: --http PORT (a live page), --snapshot FILE.png or --record DIR --every SECONDS");
  }
  if (!command_line.bind.empty() && !http) throw UsageError("--bind sets the live page's address: it needs --http");
  if (command_line.drive && !http) throw UsageError("--drive lets the live page drive the robot: it needs --http");
  if (http) return parse_http(command_line, options);
  check_seconds(command_line.after, "--after", true);
  check_seconds(command_line.every, "--every", false);
  if (snapshot) {
    if (command_line.every) throw UsageError("--every sets --record's interval; a --snapshot is one picture");
    if (command_line.count) throw UsageError("--count limits --record; a --snapshot is one picture");
    options.output = Output::kSnapshot;
    options.snapshot = command_line.snapshot;
    options.after = command_line.after.value_or(kDefaultAfter);
    return;
  }
  if (command_line.after) throw UsageError("--after applies to --snapshot; --record starts after --every");
  if (!command_line.every) throw UsageError("--record needs --every SECONDS between pictures");
  if (command_line.count && *command_line.count == 0) throw UsageError("--count must be at least 1");
  options.output = Output::kRecord;
  options.record_dir = command_line.record;
  options.every = *command_line.every;
  options.count = command_line.count;
}

}  // namespace

std::string record_file_name(std::uint64_t n) {
  char name[40];
  std::snprintf(name, sizeof name, "frame-%06llu.png", static_cast<unsigned long long>(n));
  return name;
}

ViewOptions make_view_options(const CommandLine& command_line) {
  ViewOptions options;
  client::ToolTarget target;
  try {
    target = client::split_tool_target(command_line.targets);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  options.server = target.server;
  options.devices = tools::parse_device_arguments(target.rest);
  parse_output(command_line, options);
  parse_size(command_line.size, options.render);
  if (!std::isfinite(command_line.span) || command_line.span <= 0.0) {
    throw UsageError("--span must be a positive number of metres");
  }
  options.render.span = command_line.span;
  parse_map_flags(command_line, options);
  if (command_line.key && command_line.key->empty()) throw UsageError("--key needs a key");
  options.key = command_line.key;
  if (!std::isfinite(command_line.timeout) || command_line.timeout <= 0.0) {
    throw UsageError("--timeout must be a positive number of seconds");
  }
  options.timeout = command_line.timeout;
  return options;
}

}  // namespace playerkit::player_view
