#pragma once
// The benchmark's goals: uniformly random free places on the map, each at
// least `min_separation` from where the robot will be coming from (the
// previous goal) and reachable from there with the planner's clearance.
// Drawn from the seed alone, before the run, so a seed names a goal list.

#include <cstdint>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/wavefront/wavefront_planner.hpp"

namespace playerkit::nav_bench {

struct GoalSampling {
  int count = 50;
  std::uint64_t seed = 1;
  double min_separation = 2.0;  // m from the previous goal (the start for the first)
  double extra_clearance = 0.1;  // m beyond the planner's required clearance, so goals are not against walls
};

// Throws std::runtime_error when the map has no such goal after many tries
// (a map too small or too cluttered for the separation).
std::vector<geometry::Pose2> sample_goals(wavefront::WavefrontPlanner& planner, const geometry::Pose2& start,
                                          const GoalSampling& sampling);

}  // namespace playerkit::nav_bench
