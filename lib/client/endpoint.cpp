#include "client/endpoint.hpp"

#include <stdexcept>

#include "protocol/device_address.hpp"

namespace playerkit::client {

namespace {

std::optional<std::uint16_t> parse_port(std::string_view text) {
  const auto port = protocol::parse_decimal_u16(text);
  if (!port || *port == 0) return std::nullopt;
  return port;
}

}  // namespace

std::optional<ServerEndpoint> parse_server_endpoint(std::string_view text) {
  if (text.empty()) return std::nullopt;
  ServerEndpoint endpoint;
  std::string_view host = text;
  std::optional<std::string_view> port_text;
  if (text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string_view::npos || close == 1) return std::nullopt;
    host = text.substr(1, close - 1);
    const auto after = text.substr(close + 1);
    if (!after.empty()) {
      if (after.front() != ':') return std::nullopt;
      port_text = after.substr(1);
    }
  } else if (const auto colon = text.rfind(':'); colon != std::string_view::npos) {
    // More than one colon without brackets: a bare IPv6 address, no port.
    if (text.find(':') == colon) {
      host = text.substr(0, colon);
      port_text = text.substr(colon + 1);
    }
  }
  if (port_text) {
    const auto port = parse_port(*port_text);
    if (!port) return std::nullopt;
    endpoint.port = *port;
  }
  if (!host.empty()) endpoint.host = std::string(host);
  return endpoint;
}

std::string to_string(const ServerEndpoint& endpoint) {
  const bool v6 = endpoint.host.find(':') != std::string::npos;
  return (v6 ? "[" + endpoint.host + "]" : endpoint.host) + ":" + std::to_string(endpoint.port);
}

ToolTarget split_tool_target(std::span<const std::string> arguments) {
  ToolTarget target;
  if (arguments.empty()) return target;
  const std::string& first = arguments.front();
  if (protocol::parse_device_address(first)) {
    target.rest.assign(arguments.begin(), arguments.end());
    return target;
  }
  const auto server = parse_server_endpoint(first);
  if (!server) {
    throw std::invalid_argument("'" + first + "' is neither a device (laser:0) nor a server (HOST[:PORT])");
  }
  target.server = *server;
  target.rest.assign(arguments.begin() + 1, arguments.end());
  return target;
}

}  // namespace playerkit::client
