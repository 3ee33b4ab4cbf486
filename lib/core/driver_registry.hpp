#pragma once
// Driver name -> what it serves and how to make one. The server fills a
// registry with the built-in drivers (lib/drivers) and any plugins (-d), then
// creates one driver per device section of the config file.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "config/config_file.hpp"
#include "core/clock.hpp"
#include "core/device.hpp"
#include "core/driver.hpp"
#include "core/logger.hpp"
#include "core/option_schema.hpp"
#include "core/server_clock.hpp"
#include "core/shared_connection.hpp"

namespace playerkit::core {

class DeviceTable;

// What a driver factory gets: its config section and the world around it.
struct DriverContext {
  const config::ConfigFile& config;
  const config::Section& section;  // read options with section.read_*()
  DeviceKey key;                   // the device being created
  std::string robot_name;
  DeviceTable& devices;  // other devices, for drivers built on them (amcl, writelog)
  // The server's clock; a family that keeps time of its own (a log replay, a
  // simulation) claims it here (server_clock.hpp).
  ServerClock& clock;
  Logger& logger;
  // Connections shared by the devices of one robot (shared_connection.hpp).
  ConnectionPool& connections;
};

using DriverFactory = std::function<std::unique_ptr<Driver>(const DriverContext&)>;

// What `player-drivers info` shows about a driver, and the options it takes.
struct DriverDoc {
  std::string manual_section;  // "7.39" (Player 1.5 manual)
  bool needs_hardware = false;  // opens a port, a device file or a remote server
  // Rows written by hand, for drivers without a schema (below).
  std::vector<OptionDoc> options;
  std::vector<std::string> requests;  // "GET_GEOM: the laser's pose and size", ...
  std::string example;                // a config section to paste
  // The driver's options declared once (option_schema.hpp): instantiate_devices
  // validates a section against it before the factory runs, and the tools
  // document it. Empty for drivers that read their options on their own.
  OptionSchema schema{};
  // Set for a driver whose name is known but which cannot run in any build
  // (rwi_*: RWI's Mobility middleware cannot be had): why, and what to use
  // instead. A configuration naming it is refused at the driver's name with
  // this text, before its options are read or its factory called.
  std::string unavailable{};

  // The schema's rows when there is one, else the hand-written ones.
  [[nodiscard]] std::vector<OptionDoc> option_rows() const { return schema.empty() ? options : schema.docs(); }
};

struct DriverSpec {
  std::string name;                     // as written after `driver` in a config file
  std::vector<std::uint16_t> interfaces;  // interface codes it can serve
  protocol::Access access = protocol::Access::kAll;  // r, w or a: what clients may do
  DriverFactory factory;
  DeviceLimits limits;
  std::string summary;  // one line for `drivers list`
  // Drivers of several interfaces whose devices need other queues on some of
  // them (passthrough: comms messages queue, laser scans do not).
  std::map<std::uint16_t, DeviceLimits> interface_limits{};
  // The built-in family it comes from ("p2os", "logfile"); empty for plugins.
  std::string family{};
  DriverDoc doc{};

  // `limits`, unless interface_limits says otherwise for this interface.
  [[nodiscard]] DeviceLimits limits_for(std::uint16_t interface) const;
};

class DriverRegistry {
 public:
  // A later spec of the same name replaces the earlier one (as in 1.5, so a
  // plugin may override a built-in driver).
  void add(DriverSpec spec);
  [[nodiscard]] const DriverSpec* find(std::string_view name) const;
  [[nodiscard]] bool contains(std::string_view name) const { return find(name) != nullptr; }
  // Sorted by name.
  [[nodiscard]] std::vector<const DriverSpec*> all() const;

 private:
  std::map<std::string, DriverSpec, std::less<>> drivers_;
};

}  // namespace playerkit::core
