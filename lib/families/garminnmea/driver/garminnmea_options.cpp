#include "families/garminnmea/driver/garminnmea_options.hpp"

#include <arpa/inet.h>

#include "core/option_reader.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::garminnmea {

const core::OptionSchema& garminnmea_option_schema() {
  static const core::OptionSchema schema{
      links::port_option("/dev/ttyS0").doc("the receiver's serial port, or tcp:HOST:PORT"),
      core::OptionSpec::choice("baud", 4800, {4800, 9600, 19200, 38400, 57600, 115200})
          .unit("baud")
          .doc("the receiver's line speed; NMEA's standard is 4800"),
      core::OptionSpec::integer("dgps_enable", 1, 0, 1)
          .doc("1: relay RTCM-104 corrections heard on UDP to the receiver (no multicast route: a warning, no relay)"),
      core::OptionSpec::text("dgps_group", "225.0.0.43").doc("the multicast group the corrections come on"),
      core::OptionSpec::integer("dgps_port", 7778, 1, 65535).doc("the UDP port the corrections come to"),
      core::OptionSpec::text("dgps_bind", "0.0.0.0")
          .doc("the local IPv4 address to listen on and join the group on; 127.0.0.1 keeps it on this host"),
  };
  return schema;
}

GarminNmeaSettings read_garminnmea_settings(const config::Section& section) {
  const core::OptionReader options(section, "garminnmea", garminnmea_option_schema());
  GarminNmeaSettings settings;
  settings.port = options.text("port");
  settings.baud = static_cast<int>(options.integer("baud"));
  settings.dgps_enable = options.integer("dgps_enable") != 0;
  settings.dgps_group = options.text("dgps_group");
  settings.dgps_port = static_cast<int>(options.integer("dgps_port"));
  settings.dgps_bind = options.text("dgps_bind");
  in_addr bind_address{};
  if (inet_pton(AF_INET, settings.dgps_bind.c_str(), &bind_address) != 1) {
    options.fail({"dgps_bind"}, "must be an IPv4 address, not '" + settings.dgps_bind + "'");
  }
  in_addr group{};
  if (inet_pton(AF_INET, settings.dgps_group.c_str(), &group) != 1 || (ntohl(group.s_addr) >> 28) != 0xE) {
    options.fail({"dgps_group"}, "must be an IPv4 multicast address (224.0.0.0 to 239.255.255.255), not '" +
                                     settings.dgps_group + "'");
  }
  return settings;
}

}  // namespace playerkit::drivers::garminnmea
