#pragma once
// Scan telegrams streamed after T7/T8 (sicklms200.md §2.2, sickpls.md §2):
//
//   B0 count-word values...                       all values of the variant
//   B7 first(LE) last(LE) count-word values...    values first..last (1-based)
//
// Count word (LE): bits 0-9 number of values, 11-12 partial-scan index,
// 14-15 unit (00 cm, 01 mm). The Player drivers read the count from bits
// 0-13, which agrees as long as bits 10-13 are clear.
// Each value (LE): bits 0-12 distance in the unit, 13-15 reflector level
// (measuring mode 01) or field/dazzle flags (mode 00, and every PLS value).

#include "families/sick/protocol/codes.hpp"
#include "families/sick/protocol/requests.hpp"
#include "families/sick/protocol/telegram.hpp"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

namespace playerkit::hardware::sick {

inline constexpr std::uint16_t kDistanceMask = 0x1FFF;  // bits 0-12
inline constexpr std::uint16_t kMaxDistance = kDistanceMask;
inline constexpr int kFlagsShift = 13;                   // bits 13-15
inline constexpr std::uint16_t kMaxCount = 0x3FF;        // bits 0-9

constexpr std::uint16_t distance_of(std::uint16_t value) { return value & kDistanceMask; }
constexpr std::uint8_t flags_of(std::uint16_t value) {
  return static_cast<std::uint8_t>(value >> kFlagsShift);
}
// Throws std::invalid_argument for a distance over 8191 or flags over 7.
constexpr std::uint16_t make_value(std::uint16_t distance, std::uint8_t flags = 0) {
  if (distance > kMaxDistance) throw std::invalid_argument("SICK value: distance over 8191 steps");
  if (flags > 7) throw std::invalid_argument("SICK value: flags over 7 (3 bits)");
  return static_cast<std::uint16_t>(distance | (flags << kFlagsShift));
}

struct CountWord {
  std::uint16_t count = 0;          // bits 0-9
  std::uint8_t partial_scan = 0;    // bits 11-12
  Unit unit = Unit::millimetre;     // bits 14-15

  // Throws std::invalid_argument for a count over 1023 or fields too wide.
  [[nodiscard]] std::uint16_t encode() const;
  static CountWord decode(std::uint16_t word);
  friend bool operator==(const CountWord&, const CountWord&) = default;
};

struct Scan {
  // Set for a B7 telegram: the indices of values[0] and values.back().
  std::optional<Subrange> subrange;
  std::uint8_t partial_scan = 0;
  Unit unit = Unit::millimetre;
  std::vector<std::uint16_t> values;  // raw, see distance_of() and flags_of()

  friend bool operator==(const Scan&, const Scan&) = default;
};

// The whole B0 (no subrange) or B7 telegram. Throws TelegramError for more
// than 1023 values, std::invalid_argument for count-word fields too wide.
std::vector<std::uint8_t> encode_scan(const Scan& scan, std::uint8_t status = kStatusOk);

// Reads a B0 or B7 reply. Throws TelegramError for another code, a data
// length that does not hold the count word's number of values (truncated or
// too long), or, in B7, a count that disagrees with first..last.
Scan parse_scan(const Reply& reply);

// Bytes of a B0 telegram of `count` values on the wire (732 for 361).
constexpr std::size_t scan_telegram_size(std::size_t count) {
  return kHeaderSize + 1 + 2 + 2 * count + 1 + kCrcSize;
}
constexpr std::size_t subrange_scan_telegram_size(std::size_t count) {
  return scan_telegram_size(count) + 4;
}

}  // namespace playerkit::hardware::sick
