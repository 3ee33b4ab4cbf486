#pragma once
// What a SICK laser is asked to scan, in Player's units (hundredths of a
// degree, range_res 1/10/100), and what follows from it: the variant the
// device is set to, which of its values are streamed (T7 all, or a T8
// subrange), the measuring unit, and the numbers of player_laser_config_t.
// Pure: no I/O.
//
// Beams are numbered in "segments": segment s looks at
// s * resolution - fov * 50 (0.01 deg), counter-clockwise from the
// scanner's right, as in sicklms200.md §3.3. The window is the segments
// between min_angle and max_angle (C truncation, as the 1.5 drivers).
//
// The PLS has one variant, 180 deg at 0.5 deg; a 1 deg scan takes every
// second of its values ("decimation" 2).

#include <cstdint>
#include <optional>
#include <string>

#include "families/sick/protocol/codes.hpp"
#include "families/sick/protocol/requests.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::drivers::sick_laser {

using hardware::sick::Model;

struct ScanConfig {
  int resolution_cdeg = 50;  // LMS: 25, 50, 100; PLS: 50, 100
  int fov_deg = 180;         // LMS: 100 or 180 (25 needs 100); PLS: 180
  int min_angle_cdeg = -9000;
  int max_angle_cdeg = 9000;
  int range_res = 1;  // ranges in mm (1), cm (10) or dm (100)
  bool intensity = true;  // LMS: reflector levels in bits 13-15; PLS: none

  friend bool operator==(const ScanConfig&, const ScanConfig&) = default;
};

// The defaults of a model: 180 deg at 0.5 deg, mm, intensity on (LMS).
ScanConfig default_scan_config(Model model);

// Why `model` cannot scan `config` ("resolution 25 (0.25 deg) needs fov 100"),
// or nullopt when it can.
std::optional<std::string> problem_with(const ScanConfig& config, Model model);

// The first and last segment scanned (0-based, at the config's resolution).
struct ScanWindow {
  int first = 0;
  int last = 0;
  [[nodiscard]] int count() const { return last - first + 1; }
  friend bool operator==(const ScanWindow&, const ScanWindow&) = default;
};

// Clamped to the field of view; call on a config without problems.
ScanWindow window_of(const ScanConfig& config);

// The variant the device is set to: LMS (fov, resolution), PLS its only one.
hardware::sick::Variant device_variant(const ScanConfig& config, Model model);
// Device values per reported value: 2 for a PLS at 1 deg, else 1.
int decimation(const ScanConfig& config, Model model);
// Device values in one streamed telegram.
int device_value_count(const ScanConfig& config, Model model);
// T7 when the window is every value of the variant, else T8 with the
// 1-based device indices of its first and last value.
hardware::sick::Request stream_request(const ScanConfig& config, Model model);
// The unit the device measures in: mm for range_res 1 on an LMS, otherwise
// cm (an LMS has no decimetre unit; the PLS knows only cm).
hardware::sick::Unit device_unit(const ScanConfig& config, Model model);

// min_angle and max_angle of the window (multiples of the resolution).
int window_min_angle(const ScanConfig& config);
int window_max_angle(const ScanConfig& config);

// player_laser_config_t for GET_CONFIG and the SET_CONFIG reply: the
// window's angles, intensity as it is in force (always 0 on a PLS).
protocol::LaserConfig to_laser_config(const ScanConfig& config, Model model, std::uint8_t subtype);

// A SET_CONFIG's fields as a ScanConfig. The field of view follows the
// resolution: 100 for 25, else `preferred_fov` (the `fov` option) where the
// model has it, else 180; angles beyond the field of view are clamped to it.
ScanConfig from_laser_config(const protocol::LaserConfig& request, Model model, int preferred_fov);

// "180 deg at 0.5 deg, -90..90 deg, mm, intensity on" for log lines.
std::string describe(const ScanConfig& config, Model model);

}  // namespace playerkit::drivers::sick_laser
