#pragma once
// SICK telegrams in a byte stream, for a framing::FrameFormat reader: one
// instance per direction, since a driver reads replies (address 0x80) and an
// emulator reads requests (address 0x00).
//
// Skips anything before an STX, which covers the lone ACK 0x06 and NAK 0x15
// bytes; a wrong address or a LEN no telegram has (0, below the reply's code
// and status, above kMaxBodyLength) makes the STX noise, so a reader moves
// one byte on and resynchronises. A telegram whose CRC fails is reported
// whole as bad_checksum.

#include "framing/frame_format.hpp"

namespace playerkit::hardware::sick {

class SickFrameFormat final : public framing::FrameFormat {
 public:
  // What the device sends: replies and scans, address 0x80.
  static SickFrameFormat replies() { return SickFrameFormat(true); }
  // What the host sends: requests, address 0x00.
  static SickFrameFormat requests() { return SickFrameFormat(false); }

  [[nodiscard]] std::string_view name() const override { return "sick"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override;

 private:
  explicit SickFrameFormat(bool replies) : replies_(replies) {}
  bool replies_;
};

}  // namespace playerkit::hardware::sick
