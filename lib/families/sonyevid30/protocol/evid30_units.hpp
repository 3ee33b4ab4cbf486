#pragma once
// Degrees and fields of view <-> the EVI-D30's units (sonyevid30.md §2.1,
// §3): 8.8 pan units and 12 tilt units a degree; zoom 0 (widest, the
// largest field of view) to 0x3FF (tele). The camera's pan grows clockwise,
// Player's counter-clockwise. Both directions round to the nearest unit or
// degree, so every whole-degree demand reads back as itself (1.5 truncated
// both ways and lost a degree on most of them).

namespace playerkit::hardware::sonyevid30 {

inline constexpr double kPanUnitsPerDegree = 8.8;    // 0x370 / 100
inline constexpr double kTiltUnitsPerDegree = 12.0;  // 0x12C / 25

// A Player pan (counter-clockwise degrees), clamped to +-100, in camera units.
[[nodiscard]] int pan_units(double player_degrees);
[[nodiscard]] double pan_degrees(int camera_units);
// A tilt (degrees, up positive), clamped to +-25, in camera units.
[[nodiscard]] int tilt_units(double degrees);
[[nodiscard]] double tilt_degrees(int camera_units);

// The `fov` option: the fields of view at full tele and full wide.
struct FieldOfView {
  double tele = 3;   // degrees
  double wide = 30;  // degrees
};
// A field of view in degrees as a zoom position, clamped to 0..0x3FF.
[[nodiscard]] int zoom_units(double fov_degrees, FieldOfView limits);
[[nodiscard]] double fov_degrees(int zoom_units, FieldOfView limits);

}  // namespace playerkit::hardware::sonyevid30
