#include "links/open_link.hpp"

#include "links/serial_link.hpp"
#include "links/tcp_link.hpp"

namespace playerkit::links {

std::unique_ptr<ByteLink> open_link(const LinkAddress& address, const SerialSettings& settings,
                                    LinkClock::duration connect_timeout) {
  if (address.is_tcp()) return TcpLink::connect(address.host, address.port, deadline_in(connect_timeout));
  return SerialLink::open(address.device_path, settings);
}

std::unique_ptr<ByteLink> open_link(std::string_view port, const SerialSettings& settings,
                                    LinkClock::duration connect_timeout) {
  return open_link(parse_link_address(port), settings, connect_timeout);
}

}  // namespace playerkit::links
