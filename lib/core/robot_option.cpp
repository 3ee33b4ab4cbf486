#include "core/robot_option.hpp"

#include <algorithm>

#include "config/errors.hpp"

namespace playerkit::core {

namespace {

// The option's first value as written in the file: "/dev/ttyS0" in quotes, 1 without.
std::string as_written(const config::Property& property) {
  if (property.values.empty()) return "[]";
  const config::Value& value = property.values.front();
  return value.is_string ? "\"" + value.text + "\"" : value.text;
}

config::SourceLocation value_where(const config::Property& property) {
  return property.values.empty() ? property.where : property.values.front().where;
}

}  // namespace

std::vector<RobotSection> robot_sections_with(const DriverContext& context,
                                              std::span<const std::string_view> family_drivers,
                                              std::string_view name) {
  std::vector<RobotSection> found;
  for (const config::DeviceDeclaration& declaration : context.config.devices()) {
    if (declaration.port != context.key.port) continue;
    if (std::find(family_drivers.begin(), family_drivers.end(), declaration.driver) == family_drivers.end()) {
      continue;
    }
    const config::Section& section = context.config.section(declaration.section);
    if (section.has(name)) found.push_back({&section, declaration.driver});
  }
  return found;
}

void throw_robot_values_differ(const RobotSection& second, const RobotSection& first, std::string_view name) {
  const config::Property& here = *second.section->property(name);
  const config::Property& there = *first.section->property(name);
  throw config::ConfigError(
      value_where(here), second.driver + ": " + std::string(name) + " " + as_written(here) + " differs from " +
                             as_written(there) + " given at " + config::to_string(value_where(there)) +
                             "; the devices of one robot share one connection (put another robot in its "
                             "own robot:PORT section)");
}

RobotOption robot_option(const DriverContext& context,
                         std::initializer_list<std::string_view> family_drivers,
                         std::string_view name, std::string_view fallback) {
  const auto value = robot_value(context, {family_drivers.begin(), family_drivers.size()}, name,
                                 [&](const config::Section& section, const std::string&) {
                                   return section.read_string(name, fallback);
                                 });
  return value ? RobotOption{*value, true} : RobotOption{std::string(fallback), false};
}

}  // namespace playerkit::core
