#pragma once
// The robot's units (tenths of an inch, tenths of a degree, whole inches for
// ranges) against Player's (mm, degrees). Demands round to the nearest
// tenth; the reference truncated (nomad.md §2.1), which turned 2 mm/s into 0.

#include <cstdint>

namespace playerkit::hardware::nomad {

inline constexpr double kMillimetresPerInch = 25.4;

[[nodiscard]] std::int32_t tenth_inches_from_mm(double millimetres);
[[nodiscard]] double mm_from_tenth_inches(std::int32_t tenths);
[[nodiscard]] std::int32_t tenth_degrees_from_degrees(double degrees);
[[nodiscard]] double degrees_from_tenth_degrees(std::int32_t tenths);
[[nodiscard]] double mm_from_inches(std::int32_t inches);

}  // namespace playerkit::hardware::nomad
