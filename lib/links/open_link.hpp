#pragma once
// One entry point for drivers: the `port` option in, an open link out.
//
//   auto link = links::open_link(options.port, {.baud = 38400});
//   link->set_trace_hook(...);   // --trace

#include <chrono>
#include <memory>
#include <string_view>

#include "links/byte_link.hpp"
#include "links/link_address.hpp"
#include "links/serial_settings.hpp"

namespace playerkit::links {

inline constexpr std::chrono::seconds kDefaultConnectTimeout{5};

// A SerialLink for a tty path, a TcpLink for tcp:HOST:PORT (serial settings
// then do not apply: a bridge's line is configured on the bridge).
// Throws LinkError.
std::unique_ptr<ByteLink> open_link(const LinkAddress& address, const SerialSettings& settings,
                                    LinkClock::duration connect_timeout = kDefaultConnectTimeout);

// Parses the `port` value first (LinkError(bad_address) when malformed).
std::unique_ptr<ByteLink> open_link(std::string_view port, const SerialSettings& settings,
                                    LinkClock::duration connect_timeout = kDefaultConnectTimeout);

}  // namespace playerkit::links
