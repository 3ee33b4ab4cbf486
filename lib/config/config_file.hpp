#pragma once
// A loaded Player config file: its sections (with typed reads), the devices it
// declares and the ports the server must listen on. See README.md.
//
//   auto config = ConfigFile::load("pioneer.cfg");       // throws ConfigError
//   for (const DeviceDeclaration& device : config.devices()) {
//     const Section& options = config.section(device.section);
//     ... create device.driver, reading its options from `options` ...
//   }
//   for (const Warning& w : config.unused_properties()) log(w.to_string());

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "config/section.hpp"
#include "config/source_location.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::config {

struct LoadOptions {
  // The -p port: used by devices declared before any robot section.
  std::uint16_t default_port = 6665;
  // True if a driver of that name can be instantiated. Empty: the Player 1.5
  // catalog (driver_catalog.hpp).
  std::function<bool(std::string_view)> driver_exists;
};

struct DeviceDeclaration {
  protocol::DeviceAddress address;  // interface code + index
  std::string interface_name;       // "laser"
  std::string driver;               // the `driver` property, or the interface's default driver
  bool alwayson = false;            // the `alwayson` property is non-zero
  std::uint16_t port = 6665;        // of the robot section in force, or LoadOptions::default_port
  std::string robot_name;           // from robot:<port>:<name>, else empty
  std::size_t section = 0;          // index into ConfigFile::sections()
  SourceLocation where;             // of the section's word
};

struct Warning {
  SourceLocation where;
  std::string message;

  // "file:line:col: warning: message"
  std::string to_string() const;
  friend bool operator==(const Warning&, const Warning&) = default;
};

class ConfigFile {
 public:
  // Reads, parses and checks the file. Throws ConfigError with the location of
  // the first problem.
  static ConfigFile load(const std::filesystem::path& path, const LoadOptions& options = {});
  // The same for text in memory; `filename` labels locations, and includes and
  // filename properties are resolved against its directory.
  static ConfigFile parse(std::string_view text, std::string filename,
                          const LoadOptions& options = {});

  const std::string& filename() const { return filename_; }
  const std::vector<Section>& sections() const { return sections_; }
  const Section& section(std::size_t index) const { return sections_.at(index); }

  // In file order. When the same (port, interface, index) is declared again,
  // the later declaration replaces the earlier one in the earlier one's place
  // (as 1.5's device table did) and warnings() says so.
  const std::vector<DeviceDeclaration>& devices() const { return devices_; }
  // Distinct listening ports in order of first use (a robot section uses its
  // port even if it declares no device).
  std::vector<std::uint16_t> ports() const { return ports_; }

  double unit_length() const { return units_.length; }  // metres per length unit
  double unit_angle() const { return units_.angle; }    // radians per angle unit

  // Found while loading: declarations replaced by a later one.
  const std::vector<Warning>& warnings() const { return warnings_; }
  // One warning per property that no Section::read_* or tuple_size() has
  // touched yet: "property 'foo' is defined but not used". The `driver` and
  // `alwayson` properties of device sections and the properties of replaced
  // declarations count as used. Call after the drivers have read their options.
  std::vector<Warning> unused_properties() const;

 private:
  ConfigFile() = default;
  void declare_devices(const LoadOptions& options);
  void add_device(DeviceDeclaration device);
  void use_port(std::uint16_t port);

  std::string filename_;
  std::vector<Section> sections_;
  std::vector<DeviceDeclaration> devices_;
  std::vector<std::uint16_t> ports_;
  Units units_;
  std::vector<Warning> warnings_;
};

}  // namespace playerkit::config
