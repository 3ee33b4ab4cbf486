#pragma once
// The options of nomad, nomad_position and nomad_sonar, declared once
// (core::OptionSchema), and the settings read from a configuration section.

#include <string>

#include "config/section.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::nomad {

// Nclient's fixed server port (nomad.md §1, SERV_TCP_PORT).
inline constexpr int kServerPort = 7019;

struct NomadSettings {
  std::string host;  // the server's name or address; empty: this machine's name
  int server_port = kServerPort;
  // What the link opens: "tcp:HOST:PORT".
  std::string link;
};

struct NomadSourceSettings {
  int nomad_index = 0;  // the nomad:N device this one repackages
  int nomad_port = 0;   // its Player port; 0: this device's own
};

[[nodiscard]] const core::OptionSchema& nomad_option_schema();
[[nodiscard]] const core::OptionSchema& nomad_source_option_schema();

// Throws config::ConfigError at the option's file:line:col. `machine_name`
// stands in for an empty host, as the reference's gethostname() did.
[[nodiscard]] NomadSettings read_nomad_settings(const config::Section& section, const std::string& machine_name);
[[nodiscard]] NomadSourceSettings read_nomad_source_settings(const config::Section& section, const std::string& driver);

// This machine's name (gethostname), "localhost" if it has none.
[[nodiscard]] std::string machine_name();

// What is wrong with a `port` value ("" when it is a TCP port number or
// tcp:HOST:PORT).
[[nodiscard]] std::string server_port_problem(std::string_view text);

}  // namespace playerkit::drivers::nomad
