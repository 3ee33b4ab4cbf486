#include "links/link_address.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <utility>

#include "links/link_error.hpp"

namespace playerkit::links {

namespace {

constexpr std::string_view kTcpPrefix = "tcp:";
constexpr std::string_view kForms = "expected a tty path (/dev/ttyUSB0) or tcp:HOST:PORT (tcp:127.0.0.1:4001, tcp:[::1]:4001)";

// Control characters shown as \xNN: a NUL would cut what() short.
std::string printable(std::string_view text) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string shown;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) {
      shown += "\\x";
      shown += kDigits[byte >> 4];
      shown += kDigits[byte & 0x0F];
    } else {
      shown += c;
    }
  }
  return shown;
}

[[noreturn]] void reject(std::string_view text, std::string_view why) {
  throw LinkError(LinkErrorKind::bad_address, printable(text),
                  "bad port '" + printable(text) + "': " + std::string(why) + "; " + std::string(kForms));
}

std::optional<std::uint16_t> parse_port_number(std::string_view digits) {
  if (digits.empty() || digits.size() > 5) return std::nullopt;
  unsigned value = 0;
  for (const char c : digits) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + static_cast<unsigned>(c - '0');
  }
  if (value == 0 || value > 65535) return std::nullopt;
  return static_cast<std::uint16_t>(value);
}

bool is_host_name_character(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '.' || c == '_';
}

LinkAddress parse_tcp(std::string_view text) {
  const std::string_view rest = text.substr(kTcpPrefix.size());
  if (rest.starts_with("//")) reject(text, "write tcp:HOST:PORT without '//'");
  std::string_view host;
  std::string_view port_text;
  if (rest.starts_with('[')) {
    const auto close = rest.find(']');
    if (close == std::string_view::npos) reject(text, "missing ']' after the IPv6 address");
    host = rest.substr(1, close - 1);
    in6_addr parsed{};
    if (host.empty() || inet_pton(AF_INET6, std::string(host).c_str(), &parsed) != 1) {
      reject(text, "'" + std::string(host) + "' in brackets is not an IPv6 address");
    }
    const auto after = rest.substr(close + 1);
    if (!after.starts_with(':')) reject(text, "missing ':PORT' after the address");
    port_text = after.substr(1);
  } else {
    const auto colon = rest.rfind(':');
    if (colon == std::string_view::npos) reject(text, "missing ':PORT'");
    host = rest.substr(0, colon);
    port_text = rest.substr(colon + 1);
    if (host.find(':') != std::string_view::npos) reject(text, "write IPv6 addresses in brackets, e.g. tcp:[::1]:4001");
    if (host.empty()) reject(text, "missing HOST");
    if (!std::all_of(host.begin(), host.end(), is_host_name_character)) {
      reject(text, "'" + std::string(host) + "' is not a host name or address");
    }
  }
  const auto port = parse_port_number(port_text);
  if (!port) reject(text, "'" + std::string(port_text) + "' is not a TCP port (1..65535)");
  return LinkAddress::tcp(std::string(host), *port);
}

}  // namespace

LinkAddress LinkAddress::serial(std::string path) {
  LinkAddress address;
  address.kind = Kind::serial;
  address.device_path = std::move(path);
  return address;
}

LinkAddress LinkAddress::tcp(std::string host_name, std::uint16_t port_number) {
  LinkAddress address;
  address.kind = Kind::tcp;
  address.host = std::move(host_name);
  address.port = port_number;
  return address;
}

LinkAddress parse_link_address(std::string_view text) {
  if (text.empty()) reject(text, "it is empty");
  if (text.find('\0') != std::string_view::npos) reject(text, "it contains a NUL byte");
  if (std::isspace(static_cast<unsigned char>(text.front())) != 0 ||
      std::isspace(static_cast<unsigned char>(text.back())) != 0) {
    reject(text, "it starts or ends with whitespace");
  }
  if (text.starts_with(kTcpPrefix)) return parse_tcp(text);
  // "udp://...", "rfc2217://..." would otherwise be taken for a file name
  // and fail later as a missing device, which hides the real mistake.
  if (text.find("://") != std::string_view::npos) reject(text, "only tcp:HOST:PORT network addresses are supported");
  return LinkAddress::serial(std::string(text));
}

std::string to_string(const LinkAddress& address) {
  if (!address.is_tcp()) return address.device_path;
  const bool v6 = address.host.find(':') != std::string::npos;
  return std::string(kTcpPrefix) + (v6 ? "[" + address.host + "]" : address.host) + ":" +
         std::to_string(address.port);
}

}  // namespace playerkit::links
