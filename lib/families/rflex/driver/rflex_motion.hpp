#pragma once
// A Player velocity as the RFLEX's two axis commands (rflex.md §2.1), in the
// controller's units from the robot's conversions: translation
// |xspeed x odo_distance_conversion| with the configured acceleration and
// torque 30000, rotation |yawspeed (rad) x odo_angle_conversion| with 1.5's
// acceleration 100000 and torque 35000; the direction byte is the sign.

#include <utility>

#include "families/rflex/driver/rflex_options.hpp"
#include "families/rflex/protocol/rflex_messages.hpp"

namespace playerkit::drivers::rflex {

// xspeed mm/s, yawspeed deg/s (position command units).
[[nodiscard]] std::pair<hardware::rflex::AxisCommand, hardware::rflex::AxisCommand> velocity_commands(
    double xspeed, double yawspeed, const RflexSettings& settings);

// The two SET_DIR commands of start-up: both axes at rest, the configured
// accelerations, no torque.
[[nodiscard]] std::pair<hardware::rflex::AxisCommand, hardware::rflex::AxisCommand> rest_commands(
    const RflexSettings& settings);

}  // namespace playerkit::drivers::rflex
