#pragma once
// Binary packets that start with a header byte of a known kind and end with
// a terminator byte, with no length and no checksum: Sony VISCA
// (sonyevid30.md §1): host -> camera `8x ... FF`, camera -> host
// `90 ... FF` (0x80 + camera address << 4).
//
// The protocol's other bytes never look like a header (VISCA's message
// bytes are below 0x80), so a header byte inside a packet means that packet
// lost its terminator: the search resumes at the new header, as the
// reference driver's "first 0x90 whose successor is not 0x90" rule does.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "framing/frame_format.hpp"

namespace playerkit::framing {

struct TerminatedPacketOptions {
  // A byte b starts a packet when (b & header_mask) == header_value. The
  // defaults take the replies of VISCA camera 1 (0x90); {0xF0, 0x80} takes
  // what hosts send to any camera, broadcasts 0x88 included.
  std::uint8_t header_mask = 0xFF;
  std::uint8_t header_value = 0x90;
  std::uint8_t terminator = 0xFF;
  // Header and terminator included. VISCA: 3 (`90 41 FF`) to 16 (header,
  // at most 14 message bytes, terminator).
  std::size_t min_length = 3;
  std::size_t max_length = 16;
  std::string name = "visca";
};

class TerminatedPacketFormat final : public FrameFormat {
 public:
  explicit TerminatedPacketFormat(TerminatedPacketOptions options = {});

  [[nodiscard]] std::string_view name() const override { return options_.name; }
  [[nodiscard]] FrameScan scan(std::span<const std::uint8_t> buffered) const override;

 private:
  [[nodiscard]] bool is_header(std::uint8_t byte) const {
    return (byte & options_.header_mask) == options_.header_value;
  }

  TerminatedPacketOptions options_;
};

}  // namespace playerkit::framing
