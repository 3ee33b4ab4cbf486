#pragma once
// Knobs of the TCP server. The defaults suit a robot on a LAN; tests shrink
// the time limits.

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

namespace playerkit::server {

struct ServerOptions {
  // Address the listening sockets bind to; 1.5 always used all interfaces.
  std::string bind_address = "0.0.0.0";
  // -k: clients must authenticate with this key first (truncated to 31
  // characters, as 1.5 did).
  std::optional<std::string> auth_key;
  // A client whose socket accepts nothing for this long while we have bytes for
  // it is disconnected. Data rounds due meanwhile are dropped, never queued.
  std::chrono::milliseconds stall_timeout{5000};
  // A client that sends requests but does not read the replies is
  // disconnected once this many reply bytes wait for it.
  std::size_t max_pending_reply_bytes = 4 << 20;
  // How often drivers without a thread of their own get update().
  std::chrono::milliseconds update_period{10};
  // Highest accepted DATAFREQ in effect; higher requests are served at this
  // rate (1.5's loop topped out near 100 Hz).
  unsigned max_push_frequency = 1000;
};

}  // namespace playerkit::server
