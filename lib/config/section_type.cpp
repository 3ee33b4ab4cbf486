#include "config/section_type.hpp"

#include <optional>
#include <vector>

#include "config/closest_name.hpp"
#include "text/printable.hpp"
#include "config/errors.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::config {
namespace {

std::vector<std::string_view> declarable_interface_names() {
  std::vector<std::string_view> names;
  for (const protocol::InterfaceInfo& info : protocol::all_interfaces()) {
    if (!info.default_driver.empty()) names.push_back(info.name);
  }
  return names;
}

RobotType parse_robot(std::string_view type, std::string_view rest, const SourceLocation& where) {
  const auto colon = rest.find(':');
  const std::string_view port_text = rest.substr(0, colon);
  if (port_text.empty()) {
    throw ConfigError(where,
                      "robot section without a port: auto-assigning ports is not "
                      "supported (write robot:<port> or robot:<port>:<name>)");
  }
  const auto port = protocol::parse_decimal_u16(port_text);
  if (!port || *port == 0) {
    throw ConfigError(where, "invalid port '" + text::excerpt(port_text) + "' in '" +
                                 text::excerpt(type) + "' (expected a number from 1 to 65535)");
  }
  RobotType robot{*port, ""};
  if (colon != std::string_view::npos) robot.name = std::string(rest.substr(colon + 1));
  return robot;
}

}  // namespace

std::variant<RobotType, DeviceType> parse_section_type(std::string_view type,
                                                       const SourceLocation& where) {
  const auto colon = type.find(':');
  const std::string_view head = type.substr(0, colon);
  const std::string_view rest =
      colon == std::string_view::npos ? std::string_view() : type.substr(colon + 1);
  if (head == "robot") return parse_robot(type, rest, where);

  const protocol::InterfaceInfo* info = protocol::find_interface(head);
  if (info == nullptr) {
    std::string message = "unknown interface '" + text::excerpt(head) + "'";
    const std::vector<std::string_view> known = declarable_interface_names();
    if (const auto suggestion = closest_name(head, known)) {
      message += " (did you mean '" + *suggestion + "'?)";
    }
    throw ConfigError(where, message);
  }
  if (info->default_driver.empty()) {
    throw ConfigError(where,
                      "interface '" + text::excerpt(head) + "' cannot be declared in a config file");
  }
  DeviceType device{info, 0};
  if (colon != std::string_view::npos) {
    const auto index = protocol::parse_decimal_u16(rest);
    if (!index) {
      throw ConfigError(where, "invalid index '" + text::excerpt(rest) + "' in '" +
                                   text::excerpt(type) + "' (expected a number from 0 to 65535)");
    }
    device.index = *index;
  }
  return device;
}

}  // namespace playerkit::config
