#pragma once
// Bytes from the controller's auxiliary serial ports: SERAUX (0xB0, AUX1)
// and SERAUX2 (0xB8, AUX2), and the CMUcam messages 1.5 looks for in
// SERAUX2 (p2os.md §2.5).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace playerkit::hardware::p2os {

struct AuxSerialPacket {
  std::uint8_t type = 0xB8;        // packet_type::serial_aux or serial_aux2
  std::vector<std::uint8_t> data;  // the bytes read from the port
  friend bool operator==(const AuxSerialPacket&, const AuxSerialPacket&) = default;
};

// Throws EncodeError for another type or data too long to frame.
std::vector<std::uint8_t> encode_aux_serial(const AuxSerialPacket& packet);
// Throws DecodeError for an empty payload or another type.
AuxSerialPacket decode_aux_serial(std::span<const std::uint8_t> payload);

inline constexpr std::uint8_t kCmucamStart = 0xFF;
inline constexpr std::size_t kCmucamTrackingSize = 10;  // 255 'M' + 8 values
inline constexpr std::size_t kCmucamColorSize = 8;      // 255 'S' + 6 values

// `255 'M' mx my x1 y1 x2 y2 pixels confidence`: a tracked blob.
struct CmucamTracking {
  std::uint8_t mx = 0, my = 0;  // centroid
  std::uint8_t x1 = 0, y1 = 0, x2 = 0, y2 = 0;  // bounding box
  std::uint8_t pixels = 0;
  std::uint8_t confidence = 0;

  // (y2−y1+1)·(x2−x1+1)·confidence/255 in integers, as 1.5 computes it.
  std::uint32_t area() const;

  friend bool operator==(const CmucamTracking&, const CmucamTracking&) = default;
};

// `255 'S' R G B Rvar Gvar Bvar`: the tracked colour.
struct CmucamColor {
  std::uint8_t red = 0, green = 0, blue = 0;
  std::uint8_t red_variance = 0, green_variance = 0, blue_variance = 0;
  friend bool operator==(const CmucamColor&, const CmucamColor&) = default;
};

using CmucamMessage = std::variant<CmucamTracking, CmucamColor>;

// Throws EncodeError when a value is 255 (the start byte, which would
// mislead the reader's search).
std::array<std::uint8_t, kCmucamTrackingSize> encode_cmucam_tracking(const CmucamTracking& blob);
std::array<std::uint8_t, kCmucamColorSize> encode_cmucam_color(const CmucamColor& color);

// The message 1.5 would read from SERAUX2 data: the first 255 among data
// bytes 0 ... len−10 when len <= 18, or len−19 ... len−10 when longer;
// then 'M' or 'S'. Nothing when fewer than 10 bytes, no 255 in that window,
// or another letter follows it.
std::optional<CmucamMessage> find_cmucam_message(std::span<const std::uint8_t> data);

}  // namespace playerkit::hardware::p2os
