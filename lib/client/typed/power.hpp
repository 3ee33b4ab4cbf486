#pragma once
// Battery voltage in SI units.

#include "protocol/messages/power.hpp"

namespace playerkit::client {

struct PowerState {
  double volts = 0;  // the wire carries decivolts
};

PowerState to_si(const protocol::PowerData& data);  // data, and the main-power reply

}  // namespace playerkit::client
