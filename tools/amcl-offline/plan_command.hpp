#pragma once
// amcl-offline plan: a path on a map that keeps robot radius + safety from
// every occupied or unknown cell (lib/algorithms/wavefront), its waypoints
// as CSV or JSON; or, with --compare, the path a localized run drove against
// the plan between its ends.

#include <Eigen/Core>

#include <ostream>
#include <string>

#include "localization/trajectory.hpp"
#include "plan_options.hpp"

namespace playerkit::amcl_offline {

// Returns the exit status. No path (start or goal outside the map, in or too
// near an obstacle, or unreachable) throws std::runtime_error saying which:
// exit 1, like any other failure of the work.
int run_plan(const PlanOptions& options, std::ostream& out, std::ostream& err);

// The position of the last estimate at or before `time` (a localize CSV has
// one per scan). Throws std::runtime_error naming `name` when there is none.
Eigen::Vector2d position_at(const localization::Trajectory& track, double time, const std::string& name);

}  // namespace playerkit::amcl_offline
