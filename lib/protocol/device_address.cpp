#include "protocol/device_address.hpp"

#include <charconv>

#include "protocol/interfaces.hpp"

namespace playerkit::protocol {
std::optional<std::uint16_t> parse_decimal_u16(std::string_view text) {
  // from_chars on an unsigned type takes neither sign nor leading spaces.
  std::uint16_t value = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

std::optional<DeviceAddress> parse_device_address(std::string_view text) {
  const auto colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  DeviceAddress address;
  if (const auto* info = find_interface(name)) {
    address.interface = info->code;
  } else if (const auto code = parse_decimal_u16(name)) {
    address.interface = *code;
  } else {
    return std::nullopt;
  }
  if (colon != std::string_view::npos) {
    const auto index = parse_decimal_u16(text.substr(colon + 1));
    if (!index) return std::nullopt;
    address.index = *index;
  }
  return address;
}

std::string to_string(const DeviceAddress& address) {
  const auto* info = find_interface(address.interface);
  std::string name = info ? std::string(info->name) : std::to_string(address.interface);
  return name + ":" + std::to_string(address.index);
}

}  // namespace playerkit::protocol
