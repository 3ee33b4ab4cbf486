#pragma once
// Asking a line "are you a P2OS controller?" (p2os.md §2.4): SYNC0, SYNC1,
// SYNC2; the SYNC2 reply names the robot, its class and subclass. A robot
// still connected from an earlier session (sending SIPs) gets CLOSE first, as
// the reference driver does. It is left synchronised, waiting for OPEN; a
// driver's SYNC0 restarts it.

#include <optional>

#include "families/family_spec.hpp"

namespace playerkit::families {

// nullopt when nothing P2OS answered by the deadlines. LinkErrors pass through.
std::optional<Identification> probe_p2os(const ProbeContext& line);

}  // namespace playerkit::families
