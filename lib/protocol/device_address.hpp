#pragma once
// A device as clients and config files name it: interface and index ("laser:0").

#include <compare>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace playerkit::protocol {

struct DeviceAddress {
  std::uint16_t interface = 0;  // interface code (kLaserCode, ...)
  std::uint16_t index = 0;

  friend auto operator<=>(const DeviceAddress&, const DeviceAddress&) = default;
};

// A plain decimal number 0..65535 ("7", not "+7", "7x" or " 7"); nullopt otherwise.
std::optional<std::uint16_t> parse_decimal_u16(std::string_view text);

// "laser:0", "position" (index 0), "6:1" (numeric code). nullopt for unknown
// interface names, bad or out-of-range indices.
std::optional<DeviceAddress> parse_device_address(std::string_view text);

// "laser:0"; an undefined code prints as its number: "99:0".
std::string to_string(const DeviceAddress& address);

}  // namespace playerkit::protocol
