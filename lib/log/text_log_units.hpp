#pragma once
// Units of Player 1.5's text logs against the wire's and SI's: one copy for
// the reader, the writer and their extensions (they compile in one batch).

#include <numbers>

namespace playerkit::log::text_log_units {

inline constexpr double kMmPerM = 1000.0;
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;
inline constexpr double kArcsecPerRad = 3600.0 * kDegPerRad;

// Written with 1.5 writelog's order of operations, so the last printed digit
// rounds the same way it did there.
inline double mm_to_m(double mm) { return mm / 1000.0; }
inline double deg_to_rad(double deg) { return deg * std::numbers::pi / 180.0; }

}  // namespace playerkit::log::text_log_units
