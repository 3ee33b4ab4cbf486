#include "core/robot_option.hpp"

#include <algorithm>
#include <optional>

#include "config/errors.hpp"

namespace playerkit::core {

RobotOption robot_option(const DriverContext& context,
                         std::initializer_list<std::string_view> family_drivers,
                         std::string_view name, std::string_view fallback) {
  RobotOption found{std::string(fallback), false};
  std::optional<config::SourceLocation> first_where;
  for (const config::DeviceDeclaration& declaration : context.config.devices()) {
    if (declaration.port != context.key.port) continue;
    if (std::find(family_drivers.begin(), family_drivers.end(), declaration.driver) ==
        family_drivers.end()) {
      continue;
    }
    const config::Section& section = context.config.section(declaration.section);
    const config::Property* property = section.property(name);
    if (property == nullptr) continue;
    const std::string value = section.read_string(name, fallback);
    const config::SourceLocation where =
        property->values.empty() ? property->where : property->values.front().where;
    if (!first_where) {
      found = {value, true};
      first_where = where;
    } else if (value != found.value) {
      throw config::ConfigError(
          where, declaration.driver + ": " + std::string(name) + " \"" + value + "\" differs from \"" +
                     found.value + "\" given at " + config::to_string(*first_where) +
                     "; the devices of one robot share one connection (put another robot in its "
                     "own robot:PORT section)");
    }
  }
  return found;
}

}  // namespace playerkit::core
