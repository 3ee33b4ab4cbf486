#pragma once
// Pan-tilt-zoom state and commands in SI units (wire: whole degrees, deg/s).

#include "protocol/messages/ptz.hpp"

namespace playerkit::client {

struct PtzState {
  double pan = 0;         // rad
  double tilt = 0;        // rad
  double zoom = 0;        // rad, the field of view
  double pan_speed = 0;   // rad/s
  double tilt_speed = 0;  // rad/s
};

// The same fields, sent: each rounds to the nearest whole degree (or deg/s) and
// clamps to int16; NaN or infinity throws std::invalid_argument.
using PtzCommand = PtzState;

PtzState to_si(const protocol::PtzData& data);
PtzState to_si(const protocol::PtzCommand& command);
protocol::PtzCommand to_wire(const PtzCommand& command);

}  // namespace playerkit::client
