#pragma once
// A driver's `port` option: which device a link opens.
//
//   /dev/ttyUSB0            a serial port (anything not starting with "tcp:")
//   tcp:192.168.1.20:4001   a serial-over-network bridge (ser2net) or an emulator
//   tcp:robot.local:4001    HOST may be a name,
//   tcp:[::1]:4001          an IPv4 address, or an IPv6 address in brackets

#include <cstdint>
#include <string>
#include <string_view>

namespace playerkit::links {

struct LinkAddress {
  enum class Kind { serial, tcp };
  Kind kind = Kind::serial;
  std::string device_path;  // serial: the tty path as written
  std::string host;         // tcp: name or address, without brackets
  std::uint16_t port = 0;   // tcp: 1..65535

  static LinkAddress serial(std::string path);
  static LinkAddress tcp(std::string host, std::uint16_t port);
  [[nodiscard]] bool is_tcp() const { return kind == Kind::tcp; }

  friend bool operator==(const LinkAddress&, const LinkAddress&) = default;
};

// Throws LinkError(bad_address) naming the value and the expected forms.
LinkAddress parse_link_address(std::string_view text);

// The text parse_link_address reads back: "/dev/ttyS0", "tcp:[::1]:4001".
std::string to_string(const LinkAddress& address);

}  // namespace playerkit::links
