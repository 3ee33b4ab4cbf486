#pragma once
// The LMS 2xx configuration block: the 34 bytes after F4's reply code, sent
// back after 0x77 to configure the device, and returned after F7 01
// (sicklms200.md §2.1, layout per the SICK listing as sicktoolbox uses it).
// A driver reads it, changes the measuring mode and unit, and writes every
// other byte back as it was; so the block is kept as raw bytes with named
// accessors for the fields the sheet names.

#include "families/sick/protocol/codes.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace playerkit::hardware::sick {

inline constexpr std::size_t kConfigBlockSize = 34;

struct ConfigBlock {
  // bytes[i] is the sheet's body offset i + 1 (body[0] is the F4/0x77 code).
  std::array<std::uint8_t, kConfigBlockSize> bytes{};

  // Body offsets as the sheet numbers them.
  static constexpr std::size_t kBlankingOffset = 1;         // [1-2] LE
  static constexpr std::size_t kSensitivityOffset = 3;      // stop threshold
  static constexpr std::size_t kMeasuringModeOffset = 6;    // block D
  static constexpr std::size_t kUnitOffset = 7;             // block E

  [[nodiscard]] std::uint8_t at_body_offset(std::size_t offset) const { return bytes.at(offset - 1); }
  void set_at_body_offset(std::size_t offset, std::uint8_t value) { bytes.at(offset - 1) = value; }

  [[nodiscard]] std::uint16_t blanking() const;
  [[nodiscard]] MeasuringMode measuring_mode() const {
    return static_cast<MeasuringMode>(at_body_offset(kMeasuringModeOffset));
  }
  void set_measuring_mode(MeasuringMode mode) {
    set_at_body_offset(kMeasuringModeOffset, static_cast<std::uint8_t>(mode));
  }
  [[nodiscard]] Unit unit() const { return static_cast<Unit>(at_body_offset(kUnitOffset)); }
  void set_unit(Unit unit) { set_at_body_offset(kUnitOffset, static_cast<std::uint8_t>(unit)); }

  friend bool operator==(const ConfigBlock&, const ConfigBlock&) = default;
};

}  // namespace playerkit::hardware::sick
