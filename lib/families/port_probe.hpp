#pragma once
// `player-drivers probe PORT`: which device of the registered families
// answers on a port. First what most often goes wrong
// (links::describe_open_problem: missing, permission, held by another
// process), without opening it; then each family's probes at their baud
// rates within a budget (30 s by default, room for thirty families' first
// tries): every probe's likeliest rate first, then every probe's second,
// and so on; probes of one rank in registration order.
//
// A tcp:HOST:PORT port has no speed of its own: each probe is asked once.

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "families/family_registry.hpp"

namespace playerkit::families {

struct ProbeAttempt {
  const ProbeMethod* method = nullptr;
  std::string family;
  int baud = 0;  // 0: a TCP port
};

// In the order tried.
std::vector<ProbeAttempt> probe_attempts(const FamilyRegistry& families, bool serial);

struct ProbeSettings {
  std::chrono::milliseconds first_reply{400};  // a device's answer to an attempt's first telegram
  std::chrono::milliseconds follow_up{1500};   // the rest of the exchange once it answered
  std::chrono::milliseconds budget{30000};     // the whole port
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
};

// `stop` is checked between attempts.
ProbeResult probe_port(const std::string& port, const FamilyRegistry& families, const ProbeSettings& settings,
                       const std::function<bool()>& stop);

}  // namespace playerkit::families
