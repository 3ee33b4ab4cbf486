#pragma once
// The simulator's SI readings in Player 1.5's wire units: the conversions
// every driver shares (interfaces/wire_units.hpp), under the names the
// simulated devices use.

#include "interfaces/wire_units.hpp"

namespace playerkit::drivers::sim {

using interfaces::degrees;
using interfaces::heading_degrees;
using interfaces::HeadingRange;
using interfaces::kMillimetresPerMetre;
using interfaces::radians;
using interfaces::wire_value;

}  // namespace playerkit::drivers::sim
