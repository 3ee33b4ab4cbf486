#pragma once
// How `player-drivers probe` prints what it found on a port.

#include <ostream>

#include "families/port_probe.hpp"

namespace playerkit::player_drivers {

// Text: "PORT: DRIVER at BAUD baud, MODEL" and the config line indented
// below, or "PORT: PROBLEM". JSON: one object per line.
void write_probe_result(const families::ProbeResult& result, bool json, std::ostream& out);

}  // namespace playerkit::player_drivers
