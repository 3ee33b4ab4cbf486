#pragma once
// Frames between a start and an end byte, with an escape byte (DLE) hiding
// those three bytes inside: the Amtec PowerCube / Schunk serial protocol
// (amtecpowercube.md §1): STX 0x02, a header sent as is, escaped data and
// check byte, ETX 0x03; 0x02, 0x03 and 0x10 inside are sent as 10 82,
// 10 83 and 10 90.
//
// A telegram is the frame as it was on the wire (stuffed, STX through ETX);
// unstuff() gives what it carries, stuff() makes a frame.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framing/frame_format.hpp"

namespace playerkit::framing {

// How bytes are stuffed; the defaults are the Amtec PowerCube's.
struct DleStuffing {
  std::uint8_t start = 0x02;   // STX
  std::uint8_t end = 0x03;     // ETX
  std::uint8_t escape = 0x10;  // DLE
  // An escaped byte is sent as DLE, byte + offset.
  std::uint8_t offset = 0x80;
  // Bytes right after the start sent without escaping. The PowerCube's
  // header D1 D2 is never escaped, so a 02 or 03 there is not a frame edge.
  std::size_t raw_header = 2;
};

struct DleOptions {
  DleStuffing stuffing;
  // The longest frame as sent, STX through ETX. Past it without an end, the
  // start was noise or the end was lost; the reader resynchronises.
  std::size_t max_length = 64;
  // True when the frame's content (unstuffed: header, data, check byte)
  // passes the protocol's check; empty: no check.
  std::function<bool(std::span<const std::uint8_t>)> check;
  std::string name = "dle";
};

class DleStuffedFormat final : public FrameFormat {
 public:
  explicit DleStuffedFormat(DleOptions options = {});

  [[nodiscard]] std::string_view name() const override { return options_.name; }
  [[nodiscard]] FrameScan scan(std::span<const std::uint8_t> buffered) const override;

 private:
  DleOptions options_;
};

// What a frame carries: the bytes between start and end, escapes undone,
// header as is. nullopt when `frame` is no well-formed frame (edges missing,
// an escape of a byte that needs none, an unescaped edge inside).
[[nodiscard]] std::optional<std::vector<std::uint8_t>> unstuff(std::span<const std::uint8_t> frame,
                                                               const DleStuffing& stuffing = {});

// The frame carrying `content` (header first): start, header, escaped rest, end.
[[nodiscard]] std::vector<std::uint8_t> stuff(std::span<const std::uint8_t> content, const DleStuffing& stuffing = {});

}  // namespace playerkit::framing
