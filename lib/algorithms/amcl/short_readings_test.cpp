#include "algorithms/amcl/short_readings.hpp"

#include "algorithms/amcl/synthetic_room_test_support.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>

namespace playerkit::amcl {
namespace short_readings_test {
constexpr double pi = std::numbers::pi;
const ReadingMargins margins{.short_of_map = 0.2, .through_wall = 0.5};

// In the test room, from (3, 3): the box spans y 1.5-2.5, so a ray due east
// passes it and meets the east wall.
TEST(ReadingClassifier, ShortOfTheMapFitsOrThroughAWall) {
  const auto map = test::make_room();
  const ReadingClassifier classifier(*map);
  const geometry::Pose2 sensor{3.0, 3.0, 0.0};
  using enum ReadingFit;
  // East wall's inner face at x = 9.9: 6.9 m away.
  EXPECT_EQ(classifier.classify(sensor, 0.0, 1.0, margins), short_of_map);  // a person at 1 m
  EXPECT_EQ(classifier.classify(sensor, 0.0, 6.6, margins), short_of_map);  // 0.3 m short
  EXPECT_EQ(classifier.classify(sensor, 0.0, 6.8, margins), fits);          // within the margin
  EXPECT_EQ(classifier.classify(sensor, 0.0, 6.9, margins), fits);          // the wall
  EXPECT_EQ(classifier.classify(sensor, 0.0, 7.3, margins), fits);          // 0.4 m beyond it
  EXPECT_EQ(classifier.classify(sensor, 0.0, 7.3, {.through_wall = 0.2}), through_wall);
  EXPECT_EQ(classifier.classify(sensor, 0.0, 7.5, margins), through_wall);  // 0.6 m beyond it
  EXPECT_EQ(classifier.classify(sensor, 0.0, 6.8, {.short_of_map = 0.0}), short_of_map);
  // South-east the box (6.0-7.0, 1.5-2.5) is 3.25 m along this ray.
  EXPECT_EQ(classifier.classify(sensor, -pi / 8, 3.3, margins), fits);
  EXPECT_EQ(classifier.classify(sensor, -pi / 8, 2.9, margins), short_of_map);
  EXPECT_EQ(classifier.classify(sensor, -pi / 8, 3.9, margins), through_wall);
}

TEST(ReadingClassifier, UnknownCellsAndTheMapsEdgeAreNotKnownToBeFree) {
  auto map = test::make_room();
  test::fill_box(*map, 4.0, 2.5, 4.5, 3.5, grid::CellState::unknown);
  const ReadingClassifier classifier(*map);
  const geometry::Pose2 sensor{3.0, 3.0, 0.0};
  using enum ReadingFit;
  EXPECT_EQ(classifier.classify(sensor, 0.0, 1.2, margins), fits);  // reaches the unknown patch
  EXPECT_EQ(classifier.classify(sensor, 0.0, 5.0, margins), fits);  // nor is it a wall to run through
  EXPECT_EQ(classifier.classify(sensor, 0.0, 0.7, margins), short_of_map);  // stops before it
  // A map without its outer walls: the ray leaves it.
  const grid::OccupancyGrid open(20, 20, 0.1, Eigen::Vector2d::Zero(), grid::CellState::free);
  const ReadingClassifier open_classifier(open);
  EXPECT_EQ(open_classifier.classify({1.0, 1.0, 0.0}, 0.0, 0.95, margins), fits);
  EXPECT_EQ(open_classifier.classify({1.0, 1.0, 0.0}, 0.0, 0.5, margins), short_of_map);
}

TEST(ReadingClassifierMarks, MarksShortReadingsOfAScanInTheRobotsFrame) {
  const auto map = test::make_room();
  const ReadingClassifier classifier(*map);
  test::LaserSpec spec;
  spec.beams = 5;  // -90, -45, 0, 45, 90 degrees
  const geometry::Pose2 robot{3.0, 3.0, pi / 2};  // facing north
  LaserScan scan = test::simulate_scan(*map, robot, spec);
  scan.ranges[2] = 1.0;                // straight ahead: a person
  scan.ranges[4] = scan.max_range;     // no return: never short
  scan.ranges[0] = std::numeric_limits<double>::quiet_NaN();  // unusable: left out anyway
  std::vector<unsigned char> left_out;
  EXPECT_EQ(classifier.mark_short_readings(robot, scan, margins, 100, left_out), 1u);
  EXPECT_EQ(left_out, (std::vector<unsigned char>{1, 0, 1, 0, 0}));

  // Seen from where the north wall is 1 m ahead of the sensor, the
  // person's reading fits the map.
  classifier.mark_short_readings({3.0, 4.8, pi / 2}, scan, margins, 100, left_out);
  EXPECT_EQ(left_out[2], 0);
}

TEST(ReadingClassifierMarks, ChecksAtMostTheGivenNumberEvenlySpread) {
  const auto map = test::make_room();
  const ReadingClassifier classifier(*map);
  const geometry::Pose2 robot{3.0, 3.0, 0.0};
  LaserScan scan = test::simulate_scan(*map, robot);  // 181 readings
  for (std::size_t i = 0; i < 90; ++i) scan.ranges[i] = 0.5;  // the right half hidden
  std::vector<unsigned char> left_out;
  EXPECT_EQ(classifier.mark_short_readings(robot, scan, margins, 31, left_out), 15u);  // 0, 6, ..., 84
  std::size_t kept = 0;
  for (std::size_t i = 0; i < left_out.size(); ++i) {
    if (left_out[i] == 0) {
      ++kept;
      EXPECT_EQ(i % 6, 0u) << i;
      EXPECT_GE(i, 90u);
    }
  }
  EXPECT_EQ(kept, 16u);  // 90, 96, ..., 180
}

TEST(ReadingClassifierBeams, CountsThePreparedBeamsFromAPose) {
  const auto map = test::make_room();
  const ReadingClassifier classifier(*map);
  const geometry::Pose2 robot{3.0, 3.0, 0.0};
  LaserScan scan = test::simulate_scan(*map, robot);
  scan.ranges[0] = scan.max_range;  // no return: not counted
  PreparedBeams beams;
  prepare_beams(scan, 30, beams);
  BeamFits fits = classifier.classify_beams(robot, beams, margins);
  EXPECT_EQ(fits.returned, 29u);
  EXPECT_EQ(fits.short_of_map, 0u);
  EXPECT_EQ(fits.through_wall, 0u);
  // From 0.8 m east the beams ahead run through the east wall, from 0.8 m
  // west they fall short of it; the side beams fit either way. (From the
  // east, the beam that met the box's north face near its far corner ends
  // just past the corner, in free space: short.)
  fits = classifier.classify_beams({3.8, 3.0, 0.0}, beams, margins);
  EXPECT_GT(fits.through_wall, 5u);
  EXPECT_EQ(fits.short_of_map, 1u);
  fits = classifier.classify_beams({2.2, 3.0, 0.0}, beams, margins);
  EXPECT_GT(fits.short_of_map, 5u);
  EXPECT_EQ(fits.through_wall, 0u);

  scan.ranges[87] = 0.8;  // one of the 30 kept
  scan.ranges[88] = 0.8;  // one that is not
  prepare_beams(scan, 30, beams);
  fits = classifier.classify_beams(robot, beams, margins);
  EXPECT_EQ(fits.short_of_map, 1u);
}

}  // namespace short_readings_test
}  // namespace playerkit::amcl
