#pragma once
// One B0/B7 scan telegram as player_laser_data_t (sicklms200.md §3.1,
// sickpls.md §3.1), with the differences listed in README.md: ranges in the
// unit range_res says whatever the device measured in, intensity the whole
// reflector level (0-7), zeros beyond range_count, and an inverted laser's
// angles mirrored with its beams.

#include <stdexcept>

#include "families/sick/driver/sick_scan_config.hpp"
#include "families/sick/protocol/scan.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::drivers::sick_laser {

// A scan that does not fit the configuration in force (a telegram from
// before a reconfiguration, or another device's): not published.
class ScanMismatch : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ScanConversion {
  ScanConfig config;
  Model model = Model::lms200;
  // What the device measures in (the configuration it confirmed).
  hardware::sick::Unit device_unit = hardware::sick::Unit::millimetre;
  bool invert = false;
};

// Throws ScanMismatch when the scan holds another number of values than
// the configuration streams, or is in a unit with no known step.
protocol::LaserData to_laser_data(const hardware::sick::Scan& scan, const ScanConversion& conversion);

}  // namespace playerkit::drivers::sick_laser
