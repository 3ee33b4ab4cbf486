#include "links/port_option.hpp"

#include <utility>

#include "links/link_address.hpp"
#include "links/link_error.hpp"

namespace playerkit::links {

std::string port_problem(std::string_view text) {
  try {
    (void)parse_link_address(text);
  } catch (const LinkError& e) {
    return std::string("is not a serial port or tcp:HOST:PORT: ") + e.what();
  }
  return {};
}

core::OptionSpec port_option(std::string fallback) {
  return core::OptionSpec::link_port("port", std::move(fallback), port_problem)
      .doc("the serial port, or tcp:HOST:PORT for a serial-over-network bridge");
}

}  // namespace playerkit::links
