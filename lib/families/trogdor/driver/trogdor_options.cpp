#include "families/trogdor/driver/trogdor_options.hpp"

#include "core/option_reader.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::trogdor {

const core::OptionSchema& trogdor_option_schema() {
  static const core::OptionSchema schema{
      links::port_option(kDefaultPort).doc("the robot's serial port (57600 baud, 8N1), or tcp:HOST:PORT"),
  };
  return schema;
}

std::string read_trogdor_port(const config::Section& section) {
  const core::OptionReader options(section, "trogdor", trogdor_option_schema());
  return options.text("port");
}

}  // namespace playerkit::drivers::trogdor
