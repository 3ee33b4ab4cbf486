#pragma once
// How a device protocol splits a byte stream into telegrams. Pure: a format
// only looks at bytes already received, so the same format serves a driver's
// framed reader (lib/links), an emulator's parser and a trace printer.
//
// Every device protocol here starts telegrams with a fixed header and ends
// them with a checksum, and real lines carry noise: a format says how much of
// the buffer's front is a telegram, garbage to skip, or not yet decidable.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace playerkit::framing {

struct FrameScan {
  enum class Kind {
    need_more,     // the front may start a telegram; wait for more bytes
    frame,         // the first `length` bytes are one whole, valid telegram
    bad_checksum,  // the first `length` bytes are framed right but fail the check
    skip,          // the first `length` bytes cannot start a telegram (noise)
  };
  Kind kind = Kind::need_more;
  // frame, bad_checksum: the telegram's size; skip: bytes to drop (>= 1);
  // need_more: the total buffered size at which to scan again (0: any more).
  std::size_t length = 0;

  static FrameScan need(std::size_t total = 0) { return {Kind::need_more, total}; }
  static FrameScan whole(std::size_t size) { return {Kind::frame, size}; }
  static FrameScan corrupt(std::size_t size) { return {Kind::bad_checksum, size}; }
  static FrameScan noise(std::size_t count) { return {Kind::skip, count}; }
};

class FrameFormat {
 public:
  virtual ~FrameFormat() = default;
  // "p2os", "sick": for traces and counters.
  [[nodiscard]] virtual std::string_view name() const = 0;
  // Judges the front of `buffered` (never consumes). A format must make
  // progress: skip at least one byte when the front cannot start a telegram,
  // and report a telegram whose declared length is absurd as noise, so a
  // reader resynchronises instead of waiting for bytes that never come.
  [[nodiscard]] virtual FrameScan scan(std::span<const std::uint8_t> buffered) const = 0;
};

}  // namespace playerkit::framing
