#pragma once
// Connecting to the robot (p2os.md §2.4): SYNC0, SYNC1, SYNC2 (whose reply
// names the robot), then OPEN and PULSE. The line speed is found by trying
// the sheet's list (9600, 38400, 19200, 115200, 57600) — every rate once
// per round, unlike 1.5, whose loop ran past its list (quirk 2) — and the
// whole exchange has a deadline (1.5 blocked forever on a silent robot,
// quirk 3). A robot still streaming SIPs from an earlier session is sent
// CLOSE and synchronised again.

#include <chrono>
#include <optional>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <vector>

#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/sync.hpp"
#include "links/byte_link.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::p2os {

// The sheet's probe order.
inline const std::vector<int> kP2osBaudRates{9600, 38400, 19200, 115200, 57600};

struct HandshakeSettings {
  std::string port;             // as the user wrote it, for messages
  std::vector<int> bauds = kP2osBaudRates;  // tried in this order (ignored on TCP)
  std::chrono::milliseconds reply_timeout{250};  // for each SYNC reply
  int tries_per_baud = 2;
  bool radio = false;           // radio modem: dial first ("WMS2")
};

struct HandshakeResult {
  hardware::p2os::Sync2Reply identity;
  int baud = 0;                 // the speed that answered; 0 on links without one
  bool radio_connected = false;  // the modem said "connected to address"
};

// The deadline passed with no complete handshake. The message names the
// port and the speeds tried, and says what to check.
class HandshakeFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs the handshake until it succeeds (the robot is then sending SIPs),
// `deadline` passes (HandshakeFailed) or `stop` is requested (nullopt).
// links::LinkError passes through.
std::optional<HandshakeResult> run_handshake(links::ByteLink& link, links::FramedReader& reader,
                                             const HandshakeSettings& settings, links::Deadline deadline,
                                             const std::stop_token& stop = {});

// Writes one command frame (500 ms budget).
void send_command(links::ByteLink& link, const hardware::p2os::Command& command);

}  // namespace playerkit::drivers::p2os
