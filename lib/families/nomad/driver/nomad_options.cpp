#include "families/nomad/driver/nomad_options.hpp"

#include <unistd.h>

#include <array>
#include <charconv>

#include "core/option_reader.hpp"
#include "links/link_address.hpp"
#include "links/link_error.hpp"

namespace playerkit::drivers::nomad {

namespace {

std::optional<int> port_number(std::string_view text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size() || value < 1 || value > 65535) return std::nullopt;
  return value;
}

std::string tcp_address(const std::string& host, int port) {
  const bool ipv6 = host.find(':') != std::string::npos;
  return "tcp:" + (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

}  // namespace

std::string server_port_problem(std::string_view text) {
  if (port_number(text)) return {};
  if (text.starts_with("tcp:")) {
    try {
      (void)links::parse_link_address(text);
      return {};
    } catch (const links::LinkError& e) {
      return std::string("is not a TCP port: ") + e.what();
    }
  }
  return "must be the Nomad server's TCP port (1 to 65535) or tcp:HOST:PORT";
}

std::string machine_name() {
  std::array<char, 256> name{};
  if (gethostname(name.data(), name.size() - 1) != 0 || name[0] == '\0') return "localhost";
  return name.data();
}

const core::OptionSchema& nomad_option_schema() {
  static const core::OptionSchema schema{
      core::OptionSpec::text("host", "")
          .allow_empty()
          .shown_default("this machine's name")
          .doc("the Nomad server or robot daemon (Nclient's peer); 1.5 could not set it and used this machine's name"),
      core::OptionSpec::text("port", std::to_string(kServerPort))
          .check(server_port_problem)
          .doc("the server's TCP port (1.5: fixed 7019), or tcp:HOST:PORT for both at once"),
      core::OptionSpec::text("serial_device", "/dev/ttyS0")
          .doc("1.5's direct-serial build only (direct.c); accepted and unused: the robot is reached over TCP"),
      core::OptionSpec::integer("serial_speed", 9600, -1, 38400)
          .unit("baud")
          .doc("1.5's direct-serial build only; accepted and unused"),
  };
  return schema;
}

const core::OptionSchema& nomad_source_option_schema() {
  static const core::OptionSchema schema{
      core::OptionSpec::integer("nomad_index", 0, 0, 65535).doc("the index of the nomad device this one repackages"),
      core::OptionSpec::integer("nomad_port", 0, 0, 65535)
          .doc("the Player port of that nomad device; 0: this device's own"),
  };
  return schema;
}

NomadSettings read_nomad_settings(const config::Section& section, const std::string& fallback_host) {
  const core::OptionReader options(section, "nomad", nomad_option_schema());
  NomadSettings settings;
  settings.host = options.text("host");
  const std::string port = options.text("port");
  if (port.starts_with("tcp:")) {
    const links::LinkAddress address = links::parse_link_address(port);
    if (!settings.host.empty() && settings.host != address.host) {
      options.fail({"port"}, "names host " + address.host + " and host says " + settings.host + ": give one");
    }
    settings.host = address.host;
    settings.server_port = address.port;
  } else {
    settings.server_port = *port_number(port);
  }
  if (settings.host.empty()) settings.host = fallback_host;
  settings.link = tcp_address(settings.host, settings.server_port);
  return settings;
}

NomadSourceSettings read_nomad_source_settings(const config::Section& section, const std::string& driver) {
  const core::OptionReader options(section, driver, nomad_source_option_schema());
  return {.nomad_index = options.integer("nomad_index"), .nomad_port = options.integer("nomad_port")};
}

}  // namespace playerkit::drivers::nomad
