#include "config/config_file.hpp"

#include <algorithm>
#include <utility>
#include <variant>

#include "config/closest_name.hpp"
#include "config/driver_catalog.hpp"
#include "config/errors.hpp"
#include "config/includes.hpp"
#include "config/parser.hpp"
#include "config/section_type.hpp"
#include "text/printable.hpp"

namespace playerkit::config {
namespace {

std::string unknown_driver_message(const std::string& driver, const DeviceType& device,
                                   bool is_default, const LoadOptions& options) {
  std::string message = "unknown driver '" + text::excerpt(driver) + "' for " +
                        std::string(device.interface->name) + ":" + std::to_string(device.index);
  if (is_default) {
    message += " (the default driver of '" + std::string(device.interface->name) + "')";
    return message;
  }
  // Suggest only names that would actually be accepted.
  std::vector<std::string_view> candidates;
  for (const std::string_view name : player15_drivers()) {
    if (!options.driver_exists || options.driver_exists(name)) candidates.push_back(name);
  }
  if (const auto suggestion = closest_name(driver, candidates)) {
    message += " (did you mean '" + *suggestion + "'?)";
  }
  return message;
}

}  // namespace

std::string Warning::to_string() const {
  return text::printable(config::to_string(where) + ": warning: " + message);
}

ConfigFile ConfigFile::load(const std::filesystem::path& path, const LoadOptions& options) {
  std::string text;
  try {
    text = read_config_text(path);
  } catch (const UnreadableConfigFile& error) {
    throw ConfigError(SourceLocation{path.string()}, std::string("cannot read config file: ") + error.what());
  }
  return parse(text, path.string(), options);
}

ConfigFile ConfigFile::parse(std::string_view text, std::string filename,
                             const LoadOptions& options) {
  ParsedConfig parsed = parse_text(text, filename);
  ConfigFile config;
  config.filename_ = std::move(filename);
  config.units_ = parsed.units;
  config.sections_.reserve(parsed.sections.size());
  for (ParsedSection& section : parsed.sections) {
    config.sections_.emplace_back(std::move(section), parsed.units);
  }
  config.declare_devices(options);
  return config;
}

// Every section is a declaration, taken in file order; a robot section sets
// the port and robot name of the devices that follow it (server-behaviour.md §9.4).
void ConfigFile::declare_devices(const LoadOptions& options) {
  std::uint16_t port = options.default_port;
  std::string robot_name;
  for (std::size_t i = 0; i < sections_.size(); ++i) {
    const Section& section = sections_[i];
    const auto type = parse_section_type(section.type(), section.where());
    if (const auto* robot = std::get_if<RobotType>(&type)) {
      port = robot->port;
      robot_name = robot->name;
      use_port(port);
      continue;
    }
    const auto& device = std::get<DeviceType>(type);
    const Property* driver_property = section.property("driver");
    const std::string driver = section.read_string("driver", device.interface->default_driver);
    const bool exists =
        options.driver_exists ? options.driver_exists(driver) : is_player15_driver(driver);
    if (!exists) {
      const SourceLocation& where = driver_property && !driver_property->values.empty()
                                        ? driver_property->values.front().where
                                        : section.where();
      throw ConfigError(
          where, unknown_driver_message(driver, device, driver_property == nullptr, options));
    }
    DeviceDeclaration declaration;
    declaration.address = protocol::DeviceAddress{device.interface->code, device.index};
    declaration.interface_name = std::string(device.interface->name);
    declaration.driver = driver;
    declaration.alwayson = section.read_int("alwayson", 0) != 0;
    declaration.port = port;
    declaration.robot_name = robot_name;
    declaration.section = i;
    declaration.where = section.where();
    use_port(port);
    add_device(std::move(declaration));
  }
}

void ConfigFile::add_device(DeviceDeclaration device) {
  const auto same_key = [&](const DeviceDeclaration& d) {
    return d.port == device.port && d.address == device.address;
  };
  const auto earlier = std::find_if(devices_.begin(), devices_.end(), same_key);
  if (earlier == devices_.end()) {
    devices_.push_back(std::move(device));
    return;
  }
  warnings_.push_back(Warning{
      device.where, device.interface_name + ":" + std::to_string(device.address.index) +
                        " on port " + std::to_string(device.port) +
                        " replaces the earlier declaration at " + to_string(earlier->where)});
  // The replaced section's driver is never created, so its options are not
  // worth an "unused" warning each on top of this one.
  for (const Property& property : sections_[earlier->section].properties()) property.used = true;
  *earlier = std::move(device);
}

void ConfigFile::use_port(std::uint16_t port) {
  if (std::find(ports_.begin(), ports_.end(), port) == ports_.end()) ports_.push_back(port);
}

std::vector<Warning> ConfigFile::unused_properties() const {
  std::vector<Warning> warnings;
  for (const Section& section : sections_) {
    for (const Property& property : section.properties()) {
      if (property.used) continue;
      Warning warning{property.where, "property '" + property.name + "' is defined but not used"};
      // Instances of one macro share the locations of its properties.
      if (std::find(warnings.begin(), warnings.end(), warning) == warnings.end()) {
        warnings.push_back(std::move(warning));
      }
    }
  }
  return warnings;
}

}  // namespace playerkit::config
