#include "goal_sampler.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace playerkit::nav_bench {

std::vector<geometry::Pose2> sample_goals(wavefront::WavefrontPlanner& planner, const geometry::Pose2& start,
                                          const GoalSampling& sampling) {
  // std::mt19937_64 and a hand-made uniform draw: the distributions of the
  // standard library differ between implementations, the engine does not.
  std::mt19937_64 random(sampling.seed);
  const auto uniform = [&random](double low, double high) {
    return low + (high - low) * (static_cast<double>(random() >> 11) * 0x1.0p-53);
  };
  const wavefront::ClearanceMap& map = planner.clearance();
  const Eigen::Vector2d low = map.origin();
  const Eigen::Vector2d high = low + map.resolution() * Eigen::Vector2d(map.width(), map.height());
  const double wanted_clearance = planner.parameters().required_clearance() + sampling.extra_clearance;

  std::vector<geometry::Pose2> goals;
  Eigen::Vector2d from = start.translation();
  constexpr int kTriesPerGoal = 20000;
  while (static_cast<int>(goals.size()) < sampling.count) {
    bool found = false;
    for (int attempt = 0; attempt < kTriesPerGoal && !found; ++attempt) {
      const Eigen::Vector2d place(uniform(low.x(), high.x()), uniform(low.y(), high.y()));
      const double yaw = uniform(-std::numbers::pi, std::numbers::pi);
      if ((place - from).norm() < sampling.min_separation) continue;
      if (planner.clearance().point_clearance(place, wanted_clearance) < wanted_clearance) continue;
      if (!planner.plan(from, place).found()) continue;
      goals.push_back({place.x(), place.y(), yaw});
      from = place;
      found = true;
    }
    if (!found) {
      throw std::runtime_error("no reachable free place " + std::to_string(sampling.min_separation) +
                               " m from the previous goal after " + std::to_string(kTriesPerGoal) + " tries");
    }
  }
  return goals;
}

}  // namespace playerkit::nav_bench
