#pragma once
// `player-drivers probe PORT`: which supported device answers on a port.
// First what most often goes wrong (links::describe_open_problem: missing,
// permission, held by another process), without opening it; then each
// protocol at its baud rates, the likeliest first, within a budget (10 s):
//
//   9600: SICK (8N1, LMS password), P2OS, SICK (8E1, PLS password)
//   38400: the same; 19200: the same; 115200, 57600: P2OS; 500000: SICK
//
// A tcp:HOST:PORT port has no speed of its own: each protocol is asked once.

#include <chrono>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "device_probes.hpp"
#include "links/serial_settings.hpp"

namespace playerkit::player_drivers {

enum class ProbeProtocol { p2os, sick_lms, sick_pls };

struct ProbeAttempt {
  ProbeProtocol protocol = ProbeProtocol::p2os;
  int baud = 0;  // 0: a TCP port
  links::Parity parity = links::Parity::none;
};

// In the order tried.
std::vector<ProbeAttempt> probe_attempts(bool serial);

struct ProbeSettings {
  std::chrono::milliseconds first_reply{400};  // a device's answer to an attempt's first telegram
  std::chrono::milliseconds follow_up{1500};   // the rest of the exchange once it answered
  std::chrono::milliseconds budget{10000};     // the whole port
  // -v: one line per attempt.
  std::function<void(std::string_view)> progress;
};

struct ProbeResult {
  std::string port;
  std::optional<Identification> found;
  int baud = 0;  // where it answered; 0 on a TCP port
  // Not found: why (the port's problem and its fix, or what was tried).
  std::string problem;
  bool port_unusable = false;  // missing, permission, busy, not a terminal
  bool interrupted = false;
  std::string config_line;  // found: a section to paste
  std::string note;         // found: anything the user should know first
};

// `stop` is checked between attempts.
ProbeResult probe_port(const std::string& port, const ProbeSettings& settings, const std::function<bool()>& stop);

// Text: "PORT: DRIVER at BAUD baud, MODEL" and the config line indented
// below, or "PORT: PROBLEM". JSON: one object per line.
void write_probe_result(const ProbeResult& result, bool json, std::ostream& out);

}  // namespace playerkit::player_drivers
