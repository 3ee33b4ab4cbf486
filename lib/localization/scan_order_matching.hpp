#pragma once
// Estimates matched to the truth by scan order, for logs without usable times
// (log/log_clock.hpp: file order on a synthetic clock). amcl-offline eval.

#include "localization/trajectory.hpp"

namespace playerkit::localization {

// Row k of `estimate` gets the time of truth pose k (one row per scan is what
// amcl-offline localize writes), so evaluate_trajectory pairs them whatever
// times the estimate carries. Throws std::invalid_argument when the counts
// differ: matching by order is then meaningless.
Trajectory retimed_by_scan_order(const Trajectory& estimate, const Trajectory& truth);

}  // namespace playerkit::localization
