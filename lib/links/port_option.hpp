#pragma once
// The `port` option of every driver that opens a link, declared once so
// that every family reads it the same way: a tty path or tcp:HOST:PORT
// (link_address.hpp), checked while the configuration is read, so that
// `player-serve --check` refuses "tcp:localhost" or "tcp:localhost:99999" at
// the value's file:line:col instead of at the first subscription.
//
//   schema.add(links::port_option("/dev/ttyS1").doc("the laser's serial port, or tcp:HOST:PORT"));

#include <string>
#include <string_view>

#include "core/option_schema.hpp"

namespace playerkit::links {

core::OptionSpec port_option(std::string fallback);

// What is wrong with `text` as a port ("is not a serial port or
// tcp:HOST:PORT: bad port 'tcp:x': missing ':PORT'; ..."), or empty.
std::string port_problem(std::string_view text);

}  // namespace playerkit::links
