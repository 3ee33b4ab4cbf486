#pragma once
// `player-drivers run NAME OPTION=VALUE...` as a configuration the daemon
// loads: one section per device, one option per line, so that an error the
// configuration layer reports at line:col can be told back to the user as the
// OPTION=VALUE they typed.
//
//   # player-drivers run sicklms200
//   laser:0 ( driver "sicklms200"
//     port "/tmp/laser"
//     rate 38400
//   )
//
// A family (`p2os`) gets one section per driver, numbered per interface
// (position:0, :1, :2); each option goes on the first section whose driver
// documents it, else on the first section (robot options such as `port` are
// found by every device of the robot). `--record FILE` adds a writelog device
// recording every readable one.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/driver_registry.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::player_drivers {

// OPTION=VALUE as typed.
struct OptionAssignment {
  std::string name;
  std::string value;
  friend bool operator==(const OptionAssignment&, const OptionAssignment&) = default;
};

// "rate=38400" -> {rate, 38400}. Throws UsageError: no '=', or a name that is
// not a config option name (letters, digits, '_', not starting with a digit).
OptionAssignment parse_option_assignment(std::string_view word);

// How a value is written in the configuration: numbers, [tuples] and "quoted
// strings" as typed, any other text quoted. Throws UsageError for a value the
// configuration cannot hold (a '"' inside text, a line break).
std::string config_value(std::string_view value);

struct PlanRequest {
  std::string name;  // a driver or a family
  std::vector<OptionAssignment> options;
  // A single driver serving several interfaces: which device it is (default:
  // its first interface, index 0).
  std::optional<protocol::DeviceAddress> serve_as;
  std::optional<std::string> record_file;
};

struct PlannedDevice {
  protocol::DeviceAddress address;
  const core::DriverSpec* spec = nullptr;
  std::vector<OptionAssignment> options;
};

struct RunPlan {
  std::string name;
  bool family = false;
  std::vector<PlannedDevice> devices;
  std::optional<protocol::DeviceAddress> recorder;  // --record's writelog device
  std::string config_text;
  // Configuration line -> what the user wrote that put it there:
  // "option rate=19200", "sicklms200 (laser:0)", "--record run.log".
  std::map<int, std::string> line_sources;
  // Lines holding an OPTION=VALUE, and which.
  std::map<int, OptionAssignment> option_lines;
};

// Throws UsageError: unknown name, --device for a family or an interface the
// driver does not serve, an option given twice, a value the configuration
// cannot hold, --record with nothing readable to record.
RunPlan make_run_plan(const core::DriverRegistry& registry, const PlanRequest& request);

// Each driver at its first interface, indices counted per interface in order.
std::vector<protocol::DeviceAddress> family_addresses(const std::vector<const core::DriverSpec*>& drivers);

// Where "<config_name>:L:C: message" points: L and the message after the
// location; nullopt for a message without that prefix.
struct ConfigMessage {
  int line = 0;
  std::string text;
};
std::optional<ConfigMessage> split_config_message(std::string_view config_name, std::string_view message);

// "<config_name>:L:C: message" -> "option rate=19200: message" when line L
// came from the command line; anything else is returned unchanged.
std::string explain_config_message(const RunPlan& plan, std::string_view config_name, std::string_view message);

}  // namespace playerkit::player_drivers
