#pragma once
// The JSON of a payload in SI units instead of wire units: lengths in metres,
// angles in radians, speeds in m/s and rad/s (player-cat --si, typed helpers).
// Same shape and field names as payload_to_json / message_to_json; only the
// values of fields that carry a unit change (to floating point). Laser ranges
// are multiplied by range_res on the way. Fields without a unit stay as they are.
//
// What "SI" means, field by field, is the table behind si_field_rules(). The
// choices that are not obvious:
//  * GPS latitude and longitude become decimal degrees, not radians: that is how
//    coordinates are read and written everywhere (Player 1.5's log writes them so).
//  * Scaled dimensionless values are unscaled: GPS hdop (times 10) becomes the
//    plain HDOP, localize alpha (weight times 1e6) the weight.
//  * localize covariances become m^2, m*rad and rad^2 (each element scaled by the
//    factors of its row and column axis).
//  * localize map scale (pixels per kilometre) becomes pixels per metre.
//  * Times keep their wire form: split second/microsecond pairs are already exact,
//    and fields in ms (blinkenlight period_ms, audiodsp duration) say so.
//  * Left as they are on purpose: laser range_res (a multiplier; the ranges it
//    scales are converted), position speed-prof speed/acc (driver units), raw
//    voltages, pixels, Hz, "units unspecified" velocities.
// These are the same conversions as Player 1.5's text log (logfile-format.md).

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "protocol/constants.hpp"
#include "protocol/message.hpp"

namespace playerkit::protocol {

// Throws DecodeError like payload_to_json.
nlohmann::json payload_to_si_json(std::uint16_t interface, MessageType type,
                                  std::span<const std::uint8_t> payload,
                                  std::optional<std::uint16_t> request_subtype = std::nullopt);

// message_to_json with "data" in SI units.
nlohmann::json message_to_si_json(const Message& message,
                                  std::optional<std::uint16_t> request_subtype = std::nullopt);

// The units wire fields carry, each with its SI counterpart.
enum class WireUnit {
  kMillimetre,           // -> m
  kCentimetre,           // -> m
  kMillimetrePerSecond,  // -> m/s
  kHundredthDegree,      // 0.01 deg -> rad
  kDegree,               // -> rad
  kDegreePerSecond,      // -> rad/s
  kArcSecond,            // -> rad
  kArcSecondPerSecond,   // -> rad/s
  kGpsAngle,             // 1/216000 deg (1/60 arc-second) -> deg
  kDecivolt,             // -> V
  kTenth,                // value times 10 -> value
  kMillionth,            // value times 1e6 -> value
  kPixelPerKilometre,    // -> pixels per metre
};

// Exact arithmetic where it can be: value * numerator / denominator, so that
// 1500 mm is exactly 1.5 m. from_si is the inverse, unrounded.
double to_si(WireUnit unit, double wire_value);
double from_si(WireUnit unit, double value_in_si);
std::string_view si_symbol(WireUnit unit);  // "m", "rad", "m/s", ...

// One row of the conversion table: which field of which wire struct carries what.
enum class SiRule {
  kUnit,        // units[0] applies to the value, or to every element of an array
  kPerColumn,   // units[i] applies to column i of the innermost arrays (x mm, y mm, yaw deg)
  kCovariance,  // 3x3 matrix; element [r][c] scales by the factors of units[r] and units[c]
  kLaserRanges, // millimetres times the struct's range_res (0 counts as 1)
  kNested,      // a struct (or array of structs) named by nested_struct
};

struct SiFieldRule {
  std::string_view wire_struct;  // "player_position_geom_t"
  std::string_view field;        // "pose"
  SiRule rule = SiRule::kUnit;
  std::vector<WireUnit> units;
  std::string_view nested_struct;
};

std::span<const SiFieldRule> si_field_rules();

}  // namespace playerkit::protocol
