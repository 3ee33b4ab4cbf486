#include "cat_options.hpp"

#include <algorithm>
#include <cmath>

#include "device_arguments.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::cat {
namespace {

OutputFormat parse_format(const std::string& text) {
  if (text == "text") return OutputFormat::kText;
  if (text == "json") return OutputFormat::kJson;
  if (text == "csv") return OutputFormat::kCsv;
  if (text == "log") return OutputFormat::kLog;
  throw UsageError("--format '" + text + "': expected text, json, csv or log");
}

TimeStyle parse_time_style(const std::string& text) {
  if (text == "a") return TimeStyle::kAbsolute;
  if (text == "d") return TimeStyle::kDelta;
  if (text == "z") return TimeStyle::kZero;
  throw UsageError("-t '" + text + "': expected a (absolute), d (delta) or z (zero-based)");
}

void check_rate(const CatOptions& options) {
  if (!options.rate) return;
  const double rate = *options.rate;
  if (!std::isfinite(rate) || rate <= 0.0) throw UsageError("--rate must be a positive number of Hz");
  if (!options.pull_mode() && (rate != std::floor(rate) || rate > 65535.0)) {
    throw UsageError("--rate in push modes is the server's data frequency: a whole number of Hz, 1 to 65535");
  }
}

// Flags that only make sense for some formats.
void check_format_flags(const CatOptions& options) {
  if (options.csv_dir && options.format != OutputFormat::kCsv) {
    throw UsageError("--csv-dir writes CSV files: it needs --format csv");
  }
  if (options.format == OutputFormat::kCsv && !options.csv_dir && options.devices.size() > 1) {
    throw UsageError(
        "CSV on stdout takes one device, since each device has its own columns; "
        "use --csv-dir DIR to write one file per device (DIR/" +
        csv_file_name(options.devices[0]) + ", ...)");
  }
  if (options.format == OutputFormat::kLog) {
    // Player log lines have a fixed layout, units and times of their own.
    if (!options.fields.empty()) throw UsageError("--field does not apply to --format log");
    if (options.si)
      throw UsageError("--si does not apply to --format log (log lines have units of their own)");
    if (options.time_style != TimeStyle::kAbsolute) {
      throw UsageError("-t d and -t z do not apply to --format log (log lines carry the server's times)");
    }
  }
}

}  // namespace

std::string csv_file_name(protocol::DeviceAddress device) {
  return protocol::interface_name(device.interface) + "_" + std::to_string(device.index) + ".csv";
}

CatOptions make_cat_options(const CommandLine& command_line) {
  CatOptions options;
  client::ToolTarget target;
  try {
    target = client::split_tool_target(command_line.targets);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  options.server = target.server;
  options.devices = tools::parse_device_arguments(target.rest);
  options.list = command_line.list;
  if (options.list && !options.devices.empty()) {
    throw UsageError("--list shows the server's devices: name no devices with it");
  }
  if (!options.list && options.devices.empty()) {
    throw UsageError("name at least one device to dump (e.g. laser:0), or use --list");
  }

  options.format = parse_format(command_line.format);
  if (!command_line.csv_dir.empty()) options.csv_dir = command_line.csv_dir;
  if (command_line.count && *command_line.count == 0) throw UsageError("--count must be at least 1");
  options.count = command_line.count;
  options.once = command_line.once;
  if (command_line.duration && (!std::isfinite(*command_line.duration) || *command_line.duration <= 0.0)) {
    throw UsageError("--duration must be a positive number of seconds");
  }
  options.duration = command_line.duration;
  for (const auto& field : command_line.fields) {
    try {
      options.fields.push_back(FieldPath::parse(field));
    } catch (const FieldPathError& e) {
      throw UsageError(std::string("--field: ") + e.what());
    }
  }
  const auto mode = protocol::parse_data_mode(command_line.mode);
  if (!mode) {
    throw UsageError("--mode '" + command_line.mode + "': expected push-new, push-all, pull-new or pull-all");
  }
  options.mode = *mode;
  options.rate = command_line.rate;
  check_rate(options);
  if (command_line.key && command_line.key->empty()) throw UsageError("--key needs a key");
  options.key = command_line.key;
  options.time_style = parse_time_style(command_line.timestamps);
  options.si = command_line.si;
  if (!std::isfinite(command_line.timeout) || command_line.timeout <= 0.0) {
    throw UsageError("--timeout must be a positive number of seconds");
  }
  options.timeout = command_line.timeout;
  check_format_flags(options);
  return options;
}

}  // namespace playerkit::cat
