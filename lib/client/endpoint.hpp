#pragma once
// Where a tool connects and what it names on the command line:
//
//   player-cat laser:0                       -> localhost:6665, [laser:0]
//   player-cat robot1:7000 laser:0 sonar     -> robot1:7000,   [laser:0, sonar]
//   player-cat [::1]:6665 position           -> ::1:6665,      [position]
//
// The first argument is the server unless it names a device: an interface name
// (with or without ":index") is a device, anything else is a host. A host that
// happens to be called like an interface ("laser") can be written "laser:6665"
// only if "laser:6665" is not taken as a device; name such hosts by address.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::client {

inline constexpr std::uint16_t kDefaultPort = 6665;  // PLAYER_PORTNUM

struct ServerEndpoint {
  std::string host = "localhost";
  std::uint16_t port = kDefaultPort;

  friend bool operator==(const ServerEndpoint&, const ServerEndpoint&) = default;
};

// "host", "host:port", ":port", "[v6addr]", "[v6addr]:port". nullopt when the
// port is not a number in 1..65535 or the text is empty.
std::optional<ServerEndpoint> parse_server_endpoint(std::string_view text);

// "host:port", with brackets around IPv6 addresses.
std::string to_string(const ServerEndpoint& endpoint);

struct ToolTarget {
  ServerEndpoint server;
  std::vector<std::string> rest;  // the arguments after the server, if one was given
};

// Splits a tool's positional arguments into the server (first argument, when it
// is not a device) and the rest. Throws std::invalid_argument for a first
// argument that is neither a device nor a valid HOST[:PORT].
ToolTarget split_tool_target(std::span<const std::string> arguments);

}  // namespace playerkit::client
