#include "families/sick/driver/sick_scan_conversion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace playerkit::drivers::sick_laser {

namespace sick = hardware::sick;

namespace {

// Tenths of a millimetre per device step: exact for both units.
std::optional<int> tenth_mm_per_step(sick::Unit unit) {
  switch (unit) {
    case sick::Unit::millimetre: return 10;
    case sick::Unit::centimetre: return 100;
  }
  return std::nullopt;
}

}  // namespace

protocol::LaserData to_laser_data(const sick::Scan& scan, const ScanConversion& conversion) {
  const ScanConfig& config = conversion.config;
  const auto expected = static_cast<std::size_t>(device_value_count(config, conversion.model));
  if (scan.values.size() != expected) {
    throw ScanMismatch("scan of " + std::to_string(scan.values.size()) + " values, expected " +
                       std::to_string(expected) + " for " + describe(config, conversion.model));
  }
  const auto step = tenth_mm_per_step(conversion.device_unit);
  if (!step) {
    throw ScanMismatch("the laser measures in unit code " +
                       std::to_string(static_cast<int>(conversion.device_unit)) +
                       ", which has no known step");
  }
  const ScanWindow window = window_of(config);
  const auto every = static_cast<std::size_t>(decimation(config, conversion.model));
  const bool levels = conversion.model == Model::lms200 && config.intensity;
  const double tenths_per_unit = config.range_res * 10.0;

  protocol::LaserData data;
  data.min_angle = static_cast<std::int16_t>(window_min_angle(config));
  data.max_angle = static_cast<std::int16_t>(window_max_angle(config));
  data.resolution = static_cast<std::uint16_t>(config.resolution_cdeg);
  data.range_res = static_cast<std::uint16_t>(config.range_res);
  data.range_count = static_cast<std::uint16_t>(window.count());
  for (std::size_t i = 0; i < data.range_count; ++i) {
    const std::uint16_t value = scan.values[i * every];
    const double range = std::round(sick::distance_of(value) * *step / tenths_per_unit);
    data.ranges[i] = static_cast<std::uint16_t>(
        std::min(range, double{std::numeric_limits<std::uint16_t>::max()}));
    data.intensity[i] = levels ? sick::flags_of(value) : 0;
  }
  if (conversion.invert) {
    // Upside down, the laser's beam at angle a looks at -a in the robot's
    // frame: the same beams in reverse order cover -max..-min.
    const auto count = static_cast<std::ptrdiff_t>(data.range_count);
    std::reverse(data.ranges.begin(), data.ranges.begin() + count);
    std::reverse(data.intensity.begin(), data.intensity.begin() + count);
    const std::int16_t min_angle = data.min_angle;
    data.min_angle = static_cast<std::int16_t>(-data.max_angle);
    data.max_angle = static_cast<std::int16_t>(-min_angle);
  }
  return data;
}

}  // namespace playerkit::drivers::sick_laser
