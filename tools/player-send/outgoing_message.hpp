#pragma once
// The message a command line asks for:
//
//   DEVICE cmd FIELD=VALUE...          a command (the interface's command struct)
//   DEVICE req NAME [FIELD=VALUE...]   a request by its name in the catalog
//
// Everything is checked before connecting: the device name, the verb, the
// request name, every field and value (by the struct's own codec).

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "protocol/device_address.hpp"
#include "protocol/message.hpp"

namespace playerkit::player_send {

// "position:0", "laser" (index 0), "6:1". Throws UsageError saying what is
// wrong, with a suggestion for a misspelt interface name.
protocol::DeviceAddress parse_device(std::string_view text);

// Throws UsageError naming the bad word and what is allowed there.
protocol::Message message_from_arguments(std::span<const std::string> words);

// "get-geom, set-config, ..." for error messages; "none" when there are none.
std::string request_names(std::uint16_t interface);

}  // namespace playerkit::player_send
