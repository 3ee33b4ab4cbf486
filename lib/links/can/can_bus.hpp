#pragma once
// CAN frames over a link, whichever carries them: an slcan adapter on a
// serial line (ASCII lines, opened with S<n> and O, closed with C) or a
// SocketCAN socket (16-byte records, no handshake). A driver sends and
// receives framing::CanFrame and never sees which.

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "framing/can_frame.hpp"
#include "links/byte_link.hpp"
#include "links/can/slcan.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::links::can {

enum class CanTransport { slcan, socketcan };

class CanBus {
 public:
  // `link` must outlive the bus.
  CanBus(ByteLink& link, CanTransport transport);

  // slcan: closes whatever channel an earlier session left open, sets the
  // bit rate and opens the channel, each acknowledged by the adapter within
  // `timeout` (throws ExchangeError naming the step otherwise). socketcan:
  // nothing to do (the interface's bit rate is the system's: `ip link`).
  void start(int bitrate, std::chrono::milliseconds timeout, std::function<bool()> stopping = {});
  // slcan: closes the channel (no acknowledgement awaited). Never throws.
  void stop() noexcept;

  void send(const framing::CanFrame& frame, Deadline deadline);
  // The next frame, or nullopt when none came by the deadline. Adapter
  // acknowledgements ("z", a bare CR) and refusals are counted, not returned.
  std::optional<framing::CanFrame> receive(Deadline deadline);

  [[nodiscard]] CanTransport transport() const { return transport_; }
  [[nodiscard]] std::uint64_t refusals() const { return refusals_; }
  ByteLink& link() { return link_; }

 private:
  ByteLink& link_;
  const CanTransport transport_;
  SlcanFormat slcan_format_;
  framing::CanRecordFormat record_format_;
  FramedReader reader_;
  std::uint64_t refusals_ = 0;
};

}  // namespace playerkit::links::can
