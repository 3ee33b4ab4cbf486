// The real Radish logs in tests/data/radish (see PROVENANCE.md there), read
// straight from their .gz copies. The expected counts come from
// `awk '{print $1}' LOG | sort | uniq -c` on the uncompressed logs. The issue's
// "910 FLASER in intel-corrected.log" is what `grep -c '^FLASER'` gives;
// a plain `grep -c FLASER` says 911 because the comment header line
// "# message formats defined: PARAM SYNC ODOM FLASER RLASER TRUEPOS" names it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "log/carmen_log_reader.hpp"
#include "log/log_input.hpp"

namespace playerkit::log {
namespace carmen_radish_test {

const std::filesystem::path kRadish = std::filesystem::path(PLAYERKIT_TEST_DATA_DIR) / "radish";

struct LogCounts {
  std::map<std::string, std::size_t> records;  // by keyword
  std::map<std::size_t, std::size_t> beams;    // scans by beam count
  std::optional<CarmenLaser> first_laser;
  double min_range = 1e9;
  double max_range = -1e9;
  int lines = 0;
  std::size_t comments = 0;
  std::size_t malformed = 0;
  std::map<std::string, std::size_t> unknown;
};

LogCounts count(const std::string& name) {
  const auto path = kRadish / name;
  auto in = open_log_input(path);
  CarmenLogReader reader(*in, path.string(), {.strict = true});
  LogCounts counts;
  while (auto record = reader.next()) {
    if (std::holds_alternative<CarmenParam>(*record)) ++counts.records["PARAM"];
    if (std::holds_alternative<CarmenOdometry>(*record)) ++counts.records["ODOM"];
    if (std::holds_alternative<CarmenTruePos>(*record)) ++counts.records["TRUEPOS"];
    if (auto* laser = std::get_if<CarmenLaser>(&*record)) {
      ++counts.records[std::string(carmen_laser_keyword(laser->kind))];
      ++counts.beams[laser->ranges.size()];
      if (!counts.first_laser) counts.first_laser = *laser;
      for (double range : laser->ranges) {
        counts.min_range = std::min(counts.min_range, range);
        counts.max_range = std::max(counts.max_range, range);
      }
    }
  }
  EXPECT_FALSE(in->error()) << *in->error();
  counts.lines = reader.line_number();
  counts.comments = reader.comment_lines();
  counts.malformed = reader.malformed_lines();
  counts.unknown = reader.unknown_keywords();
  return counts;
}

using Counts = std::map<std::string, std::size_t>;

TEST(CarmenRadishTest, IntelResearchLab) {
  const auto counts = count("intel-corrected.log.gz");
  EXPECT_EQ(counts.lines, 16365);
  EXPECT_EQ(counts.comments, 2u);
  EXPECT_EQ(counts.malformed, 0u);
  EXPECT_EQ(counts.records, (Counts{{"PARAM", 2}, {"ODOM", 14541}, {"FLASER", 910}}));
  EXPECT_EQ(counts.unknown, (Counts{{"NEFF", 910}}));
  EXPECT_EQ(counts.beams, (std::map<std::size_t, std::size_t>{{180, 910}}));
  EXPECT_DOUBLE_EQ(counts.min_range, 0.23);
  EXPECT_DOUBLE_EQ(counts.max_range, 81.83);
  // The first scan: what a conversion to Player needs is all there.
  ASSERT_TRUE(counts.first_laser);
  const auto& scan = *counts.first_laser;
  EXPECT_DOUBLE_EQ(scan.ranges.front(), 1.09);
  EXPECT_DOUBLE_EQ(scan.ranges[1], 1.08);
  EXPECT_DOUBLE_EQ(scan.ranges.back(), 1.23);
  EXPECT_EQ(scan.laser_pose, (CarmenPose{0.600266, -0.0320327, -0.354665}));
  EXPECT_EQ(scan.robot_pose, scan.laser_pose);
  EXPECT_EQ(scan.stamp, (CarmenStamp{32.9068, "pippo", 32.9068}));
  EXPECT_EQ(scan.config, guess_carmen_laser_config(180));
}

TEST(CarmenRadishTest, Freiburg079) {
  const auto counts = count("freiburg-079-corrected.log.gz");
  EXPECT_EQ(counts.lines, 19496);
  EXPECT_EQ(counts.comments, 2u);
  EXPECT_EQ(counts.malformed, 0u);
  EXPECT_EQ(counts.records, (Counts{{"PARAM", 187}, {"ODOM", 9725}, {"FLASER", 4791}}));
  EXPECT_EQ(counts.unknown, (Counts{{"NEFF", 4791}}));
  EXPECT_EQ(counts.beams, (std::map<std::size_t, std::size_t>{{360, 4791}}));
  ASSERT_TRUE(counts.first_laser);
  EXPECT_EQ(counts.first_laser->laser_pose, (CarmenPose{0.00123601, -0.00106807, 2.85e-05}));
  EXPECT_EQ(counts.first_laser->stamp, (CarmenStamp{0.227623, "pippo", 0.227623}));
}

TEST(CarmenRadishTest, MitCsail) {
  const auto counts = count("csail-corrected.log.gz");
  EXPECT_EQ(counts.lines, 3327);
  EXPECT_EQ(counts.comments, 2u);
  EXPECT_EQ(counts.malformed, 0u);
  EXPECT_EQ(counts.records, (Counts{{"PARAM", 119}, {"ODOM", 2394}, {"FLASER", 406}}));
  EXPECT_EQ(counts.unknown, (Counts{{"NEFF", 406}}));
  EXPECT_EQ(counts.beams, (std::map<std::size_t, std::size_t>{{361, 406}}));
  ASSERT_TRUE(counts.first_laser);
  EXPECT_DOUBLE_EQ(counts.first_laser->ranges.front(), 81.91);
  // Six significant digits in this log's times (see PROVENANCE.md).
  EXPECT_DOUBLE_EQ(counts.first_laser->stamp.ipc_timestamp, 1.13486e+09);
}

TEST(CarmenRadishTest, FlirtlibRobotLaserExcerpt) {
  const auto counts = count("intel-lab.flirtlib.excerpt.log.gz");
  EXPECT_EQ(counts.lines, 310);
  EXPECT_EQ(counts.comments, 2u);  // "#SEQUENTIAL EDGES", "#LOOP EDGES"
  EXPECT_EQ(counts.malformed, 0u);
  EXPECT_EQ(counts.records, (Counts{{"ROBOTLASER1", 150}}));
  EXPECT_EQ(counts.unknown, (Counts{{"EDGE2", 8}, {"VERTEX2", 150}}));
  EXPECT_EQ(counts.beams, (std::map<std::size_t, std::size_t>{{180, 150}}));
  ASSERT_TRUE(counts.first_laser);
  const auto& scan = *counts.first_laser;
  EXPECT_EQ(scan.config, (CarmenLaserConfig{0, -1.570796, 3.141593, 0.017453, 50, 0.1, 0}));
  EXPECT_FALSE(scan.config_guessed);
  EXPECT_DOUBLE_EQ(scan.ranges[0], 81.83);
  EXPECT_DOUBLE_EQ(scan.ranges[1], 3.36);
  EXPECT_EQ(scan.laser_pose, (CarmenPose{4.775, -5.841, -1.686332}));
  ASSERT_TRUE(scan.motion);
  EXPECT_EQ(scan.motion->turn_axis, 0.0);
  EXPECT_EQ(scan.stamp, (CarmenStamp{976053557.767368, "x", 700.430084}));
}

}  // namespace carmen_radish_test
}  // namespace playerkit::log
