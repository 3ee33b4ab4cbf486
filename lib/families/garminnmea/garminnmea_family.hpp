#pragma once
// The garminnmea family as the tools see it: its probe, trace framing and emulator.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec garminnmea_family();

// Whether an NMEA receiver talks on the line (two checksummed sentences), for `probe`.
std::optional<Identification> probe_garminnmea(const ProbeContext& line);

}  // namespace playerkit::families
