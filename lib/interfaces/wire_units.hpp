#pragma once
// SI values (metres, radians, volts) in Player 1.5's wire units: millimetres,
// degrees, hundredths of a degree, decivolts. Rounded to the nearest unit and
// clamped to the field's type: 1.5's drivers truncated, so 0.9999 m went out
// as 999 mm (docs/compatibility.md "Simulator").

#include <cstdint>

namespace playerkit::interfaces {

inline constexpr double kMillimetresPerMetre = 1000.0;

// Rounded and clamped to the range of the field type T; NaN is 0.
template <class T>
[[nodiscard]] T wire_value(double value);

[[nodiscard]] double degrees(double radians);
[[nodiscard]] double radians(double degrees);

// Heading in whole degrees: [0, 360) as Stage 1.3 and P2OS reported it, or
// (-180, 180] as Gazebo did.
enum class HeadingRange { from_0_to_360, from_minus_180_to_180 };
[[nodiscard]] std::int32_t heading_degrees(double radians, HeadingRange range);

extern template std::int16_t wire_value<std::int16_t>(double);
extern template std::uint16_t wire_value<std::uint16_t>(double);
extern template std::int32_t wire_value<std::int32_t>(double);
extern template std::uint32_t wire_value<std::uint32_t>(double);

}  // namespace playerkit::interfaces
