#include "algorithms/amcl/beam_model.hpp"

#include "algorithms/amcl/laser_model_test_support.hpp"
#include "algorithms/amcl/synthetic_room_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace playerkit::amcl {
namespace beam_model_test {

using test::scores;

TEST(BeamModel, BeamLikelihoodIsTheFourPartMixture) {
  const LaserModelSettings s;
  const double norm = 1.0 / (std::sqrt(2 * std::numbers::pi) * 0.2);
  // Reading 3.0 where the map says 3.1: hit + short + random.
  EXPECT_NEAR(BeamModel::log_beam_likelihood(3.0, false, 3.1, 8.0, s),
              std::log(0.95 * norm * std::exp(-0.5 * 0.25) + 0.1 * 0.1 * std::exp(-0.3) +
                       0.05 / 8.0),
              1e-12);
  // Reading beyond the expected range: no short term.
  EXPECT_NEAR(BeamModel::log_beam_likelihood(3.2, false, 3.1, 8.0, s),
              std::log(0.95 * norm * std::exp(-0.5 * 0.25) + 0.05 / 8.0), 1e-12);
}

TEST(BeamModel, NoReturnIsAMissNotAFarHit) {
  const LaserModelSettings s;
  // Nothing within range on the map: a no-return reading is what a perfect
  // sensor reads, and scores like a hit.
  const double open = BeamModel::log_beam_likelihood(8.0, true, 8.0, 8.0, s);
  const double hit = BeamModel::log_beam_likelihood(3.0, false, 3.0, 8.0, s);
  EXPECT_GT(open, hit);
  // A wall at 2 m: the no-return reading scores z_max — a plausible miss —
  // well above a finite reading at 7.9 m (random clutter), and far below
  // a correct reading.
  const double missed = BeamModel::log_beam_likelihood(8.0, true, 2.0, 8.0, s);
  EXPECT_NEAR(missed, std::log(0.05), 1e-9);
  const double clutter = BeamModel::log_beam_likelihood(7.9, false, 2.0, 8.0, s);
  EXPECT_GT(missed, clutter);
  EXPECT_LT(missed, BeamModel::log_beam_likelihood(2.0, false, 2.0, 8.0, s) - 3.0);
}

// From three poses of the room, scans cast in `world` score the true pose
// above poses 30 cm or ten degrees off it.
void expect_true_pose_wins(const BeamModel& model, const grid::OccupancyGrid& world) {
  for (const geometry::Pose2& truth :
       {test::true_pose, geometry::Pose2{8.0, 4.5, -2.5}, geometry::Pose2{4.0, 1.0, 3.1}}) {
    const auto particles = test::true_and_offset_poses(truth);
    const auto s = scores(model, particles, test::simulate_scan(world, truth));
    for (std::size_t i = 1; i < s.size(); ++i) EXPECT_GT(s[0] - s[i], 3.0) << "offset pose " << i;
  }
}

TEST(BeamModel, TruePoseBeatsPosesOffByThirtyCentimetresOrTenDegrees) {
  const auto map = test::make_room();
  const BeamModel model(map);
  expect_true_pose_wins(model, *map);
}

// A map made from a log (amcl-offline map) is free only where beams went:
// far from the robot's path, cells between neighbouring beams stay unknown.
// The expected range passes them: only occupied cells stop it. (Stopping at
// unknown cells, as 1.5's map_calc_range does, cut expected ranges short
// there, so that a tracked robot on Radish Edmonton was never found.)
TEST(BeamModel, UnknownStripesDoNotStopTheExpectedRange) {
  const auto clean = test::make_room();
  auto striped = std::make_shared<grid::OccupancyGrid>(*clean);
  for (int row = 0; row < striped->height(); ++row) {
    for (int col = 0; col < striped->width(); col += 3) {
      if (striped->at(col, row) == grid::CellState::free) striped->set(col, row, grid::CellState::unknown);
    }
  }
  const BeamModel model(striped);
  expect_true_pose_wins(model, *clean);
}

TEST(BeamModel, NoReturnReadingsFavourPosesWithNothingInRange) {
  // From the room's corner looking along the diagonal nothing lies within
  // 8 m, so the simulated scan has no-return readings; the true pose still
  // wins, and a blind scan prefers poses that face open space over poses
  // facing a near wall.
  const auto map = test::make_room();
  const BeamModel model(map);
  const geometry::Pose2 corner{0.6, 0.6, std::atan2(5.3, 9.3)};
  test::LaserSpec narrow;
  narrow.field_of_view = 0.2;
  narrow.beams = 11;
  const LaserScan scan = test::simulate_scan(*map, corner, narrow);
  for (double r : scan.ranges) ASSERT_GE(r, scan.max_range);
  const std::vector<Particle> particles{{corner, 1.0}, {{0.6, 0.6, -2.4}, 1.0}};
  const auto s = scores(model, particles, scan);
  EXPECT_GT(s[0] - s[1], 11 * 3.0);
}

}  // namespace beam_model_test
}  // namespace playerkit::amcl
