#include "navigation_loop.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "goal_sampler.hpp"
#include "navigation_setup.hpp"

namespace playerkit::nav_bench {
namespace navigation_loop_test {

const std::filesystem::path kData = PLAYERKIT_DATA_DIR;

std::vector<GoalOutcome> drive(int goals, std::uint64_t seed) {
  const NavigationSetup setup = read_navigation_setup(kData / "config/nav-sim.cfg");
  NavigationLoop loop(kData / "worlds/simple.world", setup, seed);
  std::vector<GoalOutcome> outcomes;
  for (const geometry::Pose2& goal : sample_goals(loop.reference_planner(), loop.true_pose(),
                                                  {.count = goals, .seed = seed})) {
    outcomes.push_back(loop.drive_to(goal));
  }
  return outcomes;
}

// The newcomer's loop of data/config/nav-sim.cfg in the bundled cave: a few
// random goals, each reached in time without touching a wall, and the same
// run again from the same seed.
TEST(NavigationLoop, TheBundledLoopReachesRandomGoalsInTheCaveAndRepeatsItself) {
  const std::vector<GoalOutcome> first = drive(3, 4);
  ASSERT_EQ(first.size(), 3u);
  for (const GoalOutcome& goal : first) {
    EXPECT_TRUE(goal.success) << "(" << goal.goal.x << ", " << goal.goal.y << "): " << goal.ending << " after "
                              << goal.time_s << " s of " << goal.time_limit_s;
    EXPECT_EQ(goal.collisions, 0);
    EXPECT_GT(goal.min_clearance_m, 0.0);
    EXPECT_GE(goal.path_ratio(), 0.95) << "shorter than the shortest path";
  }
  const std::vector<GoalOutcome> again = drive(3, 4);
  ASSERT_EQ(again.size(), 3u);
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(again[i].path_m, first[i].path_m) << "goal " << i;
    EXPECT_EQ(again[i].time_s, first[i].time_s) << "goal " << i;
  }
}

TEST(NavigationLoop, AConfigurationWithoutTheLoopsDriversIsNamed) {
  const auto folder = std::filesystem::temp_directory_path();
  const auto file = folder / "navigation_loop_test_no_wavefront.cfg";
  {
    std::ofstream out(file);
    out << "position:1 ( driver \"vfh\" )\n";
  }
  try {
    (void)read_navigation_setup(file);
    FAIL() << "accepted a configuration without amcl";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no section with driver \"amcl\""), std::string::npos) << e.what();
  }
  std::filesystem::remove(file);
}

}  // namespace navigation_loop_test
}  // namespace playerkit::nav_bench
