#pragma once
// Every wait in lib/links ends at a deadline on the steady clock, so a caller
// that loops over several reads keeps one overall budget.

#include <chrono>

namespace playerkit::links {

using LinkClock = std::chrono::steady_clock;
using Deadline = LinkClock::time_point;

inline Deadline deadline_in(LinkClock::duration timeout) { return LinkClock::now() + timeout; }

}  // namespace playerkit::links
