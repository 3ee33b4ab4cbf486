#pragma once
// What a section's word declares (server-behaviour.md §9.4): a robot block
// "robot:<port>[:<name>]" or a device "<interface>[:<index>]".

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "config/source_location.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::config {

struct RobotType {
  std::uint16_t port = 0;
  std::string name;  // empty when not given; may itself contain ':'
};

struct DeviceType {
  const protocol::InterfaceInfo* interface = nullptr;  // never null; always declarable
  std::uint16_t index = 0;                             // 0 when not given
};

// Throws ConfigError at `where` for a robot without a port (1.5 would have to
// auto-assign one, which it never supported), a port or index that is not a
// plain decimal number in range, an unknown interface (suggesting the closest
// name) and an interface that cannot be declared (player, idar, ...).
std::variant<RobotType, DeviceType> parse_section_type(std::string_view type,
                                                       const SourceLocation& where);

}  // namespace playerkit::config
