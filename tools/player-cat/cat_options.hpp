#pragma once
// What player-cat was asked to do, checked: the command line as CLI11 fills it
// (CommandLine, plain strings and numbers) becomes CatOptions, or a UsageError
// that names the flag at fault. Pure, so the rules are unit-tested.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "client/endpoint.hpp"
#include "field_path.hpp"
#include "formatters.hpp"
#include "exit_status.hpp"
#include "protocol/constants.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::cat {

// 1: connection, server, device or output problems.
using tools::kExitFailure;
using tools::kExitOk;
using tools::kExitUsage;
using tools::UsageError;

enum class OutputFormat { kText, kJson, kCsv, kLog };
// Shared with player-log (tools/common).
using tools::FieldPath;
using tools::FieldPathError;
using tools::TimeStyle;

// The flags as typed; empty strings and nullopt mean "not given".
struct CommandLine {
  std::vector<std::string> targets;  // [HOST[:PORT]] DEVICE...
  std::string format = "text";
  std::string csv_dir;
  std::optional<std::uint64_t> count;
  bool once = false;
  std::optional<double> duration;
  std::vector<std::string> fields;
  std::string mode = "push-new";
  std::optional<double> rate;
  std::optional<std::string> key;
  std::string timestamps = "a";
  bool si = false;
  bool list = false;
  double timeout = 5.0;
};

struct CatOptions {
  client::ServerEndpoint server;
  std::vector<protocol::DeviceAddress> devices;
  OutputFormat format = OutputFormat::kText;
  std::optional<std::filesystem::path> csv_dir;
  std::optional<std::uint64_t> count;  // data messages in total
  bool once = false;                   // one data message per device
  std::optional<double> duration;      // seconds
  std::vector<FieldPath> fields;
  protocol::DataMode mode = protocol::DataMode::kPushNew;
  // Push modes: the server's frequency (whole Hz). Pull modes: how often
  // player-cat asks for a round (kDefaultPullRate when not given).
  std::optional<double> rate;
  std::optional<std::string> key;
  TimeStyle time_style = TimeStyle::kAbsolute;
  bool si = false;
  bool list = false;
  double timeout = 5.0;  // seconds, for connecting and each request

  [[nodiscard]] bool pull_mode() const {
    return mode == protocol::DataMode::kPullNew || mode == protocol::DataMode::kPullAll;
  }
};

inline constexpr double kDefaultPullRate = 10.0;  // Hz

// Throws UsageError.
CatOptions make_cat_options(const CommandLine& command_line);

// "laser_0.csv": the file --csv-dir writes for a device.
std::string csv_file_name(protocol::DeviceAddress device);

}  // namespace playerkit::cat
