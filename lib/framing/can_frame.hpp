#pragma once
// CAN frames as bytes. No device sheet defines a byte-stream shape for CAN
// (the Segway RMP's sheet, segwayrmp.md §1, reads whole frames from a CAN
// library or a SocketCAN socket), so this is the shape a SocketCAN raw socket
// reads and writes: Linux's `struct can_frame`, 16 bytes per frame:
//
//   offset 0  can_id, 32 bits: identifier in bits 0-28 (11 bits for a
//             standard frame), bit 29 error frame, bit 30 remote
//             request (RTR), bit 31 extended (29-bit) identifier
//   offset 4  len (formerly can_dlc): payload bytes, 0-8
//   offset 5  padding, offset 6 reserved, offset 7 len8_dlc (only for the
//             optional 9-15 DLC codes of an 8-byte payload): written as 0
//   offset 8  data, 8 bytes; those past `len` are written as 0
//
// The kernel keeps can_id in host byte order; the encoding here is
// little-endian, the order of every Linux host playerkit runs on (x86-64,
// arm64), so a record from a socket or a recorded stream decodes as is.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "framing/frame_format.hpp"

namespace playerkit::framing {

struct CanFrame {
  std::uint32_t id = 0;       // 11 bits, or 29 when extended
  bool extended = false;
  bool remote = false;        // a remote transmission request: no data, dlc says how much is asked for
  std::uint8_t dlc = 0;       // 0-8
  std::array<std::uint8_t, 8> data{};  // bytes past dlc are 0

  friend bool operator==(const CanFrame&, const CanFrame&) = default;
};

inline constexpr std::size_t kCanRecordSize = 16;
inline constexpr std::uint32_t kCanExtendedFlag = 0x80000000u;
inline constexpr std::uint32_t kCanRemoteFlag = 0x40000000u;
inline constexpr std::uint32_t kCanErrorFlag = 0x20000000u;
inline constexpr std::uint32_t kCanStandardIdMask = 0x7ffu;
inline constexpr std::uint32_t kCanExtendedIdMask = 0x1fffffffu;

// The 16-byte record. Throws std::invalid_argument for a frame no bus
// carries (an id beyond its 11 or 29 bits, dlc above 8).
[[nodiscard]] std::array<std::uint8_t, kCanRecordSize> encode_can_frame(const CanFrame& frame);

// The frame in a 16-byte record; nullopt for a record that holds no data or
// remote frame: too short, dlc above 8, a standard id beyond 11 bits, or an
// error frame (the kernel's bus-error reports, which only a socket that
// asked for them receives). Padding and reserved bytes are not checked.
[[nodiscard]] std::optional<CanFrame> decode_can_frame(std::span<const std::uint8_t> record);

// A stream of 16-byte records, as read from a SocketCAN raw socket or a
// recording of one. Such a stream carries no sync marker, so a record that
// does not decode is dropped whole: dropping one byte would only misalign
// every record after it.
class CanRecordFormat final : public FrameFormat {
 public:
  [[nodiscard]] std::string_view name() const override { return "can"; }
  [[nodiscard]] FrameScan scan(std::span<const std::uint8_t> buffered) const override;
};

}  // namespace playerkit::framing
