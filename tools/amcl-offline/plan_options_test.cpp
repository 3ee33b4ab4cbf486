#include "plan_options.hpp"

#include <gtest/gtest.h>

namespace playerkit::amcl_offline {
namespace plan_options_test {

PlanCommand plan_from_to(const std::string& start, const std::string& goal) {
  PlanCommand command;
  command.map = "map.yaml";
  command.start = start;
  command.goal = goal;
  return command;
}

void expect_usage_error(const PlanCommand& command, const std::string& words) {
  try {
    make_plan_options(command);
    ADD_FAILURE() << "accepted; expected an error about " << words;
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(PlanOptions, StartAndGoalAreParsedAndTheDefaultsAre1_5s) {
  const PlanOptions options = make_plan_options(plan_from_to("1.5,-2", "-3.25,4e1"));
  ASSERT_TRUE(options.start && options.goal);
  EXPECT_EQ(*options.start, Eigen::Vector2d(1.5, -2.0));
  EXPECT_EQ(*options.goal, Eigen::Vector2d(-3.25, 40.0));
  EXPECT_EQ(options.planner.robot_radius, 0.15);
  EXPECT_EQ(options.planner.safety_distance, 0.15);
  EXPECT_EQ(options.format, PlanFormat::csv);
  EXPECT_EQ(options.output, "-");
  EXPECT_FALSE(options.compare);
}

TEST(PlanOptions, FlagsReachTheOptions) {
  PlanCommand command = plan_from_to("0,0", "1,1");
  command.robot_radius = 0.25;
  command.safety = 0.0;
  command.format = "json";
  command.scale = 0.05;
  command.negate = true;
  command.origin = "0,0";
  command.plot = "p.png";
  command.output = "out.json";
  const PlanOptions options = make_plan_options(command);
  EXPECT_EQ(options.planner.robot_radius, 0.25);
  EXPECT_EQ(options.planner.safety_distance, 0.0);
  EXPECT_EQ(options.format, PlanFormat::json);
  EXPECT_EQ(options.map_loading.resolution, 0.05);
  EXPECT_TRUE(options.map_loading.negate);
  EXPECT_EQ(options.map_loading.origin, Eigen::Vector2d(0.0, 0.0));
  EXPECT_EQ(options.plot, "p.png");
  EXPECT_EQ(options.output, "out.json");
}

TEST(PlanOptions, TheStartMayBeAMomentOfATrack) {
  PlanCommand command = plan_from_to("0,0", "1,1");
  command.start.reset();
  command.track = "est.csv";
  command.at = 12.5;
  const PlanOptions options = make_plan_options(command);
  EXPECT_FALSE(options.start);
  EXPECT_EQ(options.track, "est.csv");
  EXPECT_EQ(options.at, 12.5);
}

TEST(PlanOptions, CompareTakesTheTrackAlone) {
  PlanCommand command;
  command.map = "map.yaml";
  command.track = "est.csv";
  command.compare = true;
  PlanOptions options = make_plan_options(command);
  EXPECT_TRUE(options.compare);
  EXPECT_EQ(options.format, PlanFormat::text);
  command.format = "json";
  EXPECT_EQ(make_plan_options(command).format, PlanFormat::json);
  command.format = "csv";
  expect_usage_error(command, "text or json");
  command.format.reset();
  command.goal = "1,1";
  expect_usage_error(command, "no --start, --goal or --at");
  command.goal.reset();
  command.track.reset();
  expect_usage_error(command, "--compare needs --track");
}

TEST(PlanOptions, MistakesNameTheirFlag) {
  PlanCommand command = plan_from_to("0,0", "1,1");
  command.goal.reset();
  expect_usage_error(command, "--goal X,Y");

  for (const char* bad : {"1", "1,2,3", "a,2", "1,", ",1", "1,nan", "1,inf", "1 ,2"}) {
    expect_usage_error(plan_from_to(bad, "1,1"), "--start: '");
    expect_usage_error(plan_from_to("1,1", bad), "--goal: '");
  }

  command = plan_from_to("0,0", "1,1");
  command.track = "est.csv";
  command.at = 3.0;
  expect_usage_error(command, "exclude each other");
  command.start.reset();
  command.track.reset();
  expect_usage_error(command, "--at needs --track");
  command.at.reset();
  command.track = "est.csv";
  expect_usage_error(command, "--track needs --at");
  command.track.reset();
  expect_usage_error(command, "--start X,Y or --track");

  command = plan_from_to("0,0", "1,1");
  command.robot_radius = 0.0;
  expect_usage_error(command, "--robot-radius must be > 0");
  command.robot_radius = 0.2;
  command.safety = -0.1;
  expect_usage_error(command, "--safety must be >= 0");
  command.safety = 0.1;
  command.format = "xml";
  expect_usage_error(command, "csv or json");
  command.format.reset();
  command.scale = 0.0;
  expect_usage_error(command, "--scale must be > 0");
  command.scale.reset();
  command.origin = "1;2";
  expect_usage_error(command, "--origin: '1;2' is not X,Y");
}

}  // namespace plan_options_test
}  // namespace playerkit::amcl_offline
