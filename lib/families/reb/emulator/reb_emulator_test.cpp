// The emulated UBot on a simulated clock, against reb.md §6.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "families/reb/emulator/reb_emulator.hpp"

namespace playerkit::emulators {
namespace reb_emulator_test {

using namespace std::chrono_literals;
using hardware::reb::Motor;

struct Session {
  Session() : board(RebEmulatorOptions{}) {}
  explicit Session(const RebEmulatorOptions& options) : board(options) {}
  RebEmulator board;
  Duration now{0};

  // Writes `line` and CR, lets `wait` pass, returns everything the board said.
  std::string say(const std::string& line, Duration wait = 10ms) {
    const std::string bytes = line + "\r";
    board.receive(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), now, 38400);
    return run(wait);
  }
  std::string run(Duration wait) {
    now += wait;
    board.advance(now);
    std::string text;
    for (const Telegram& telegram : board.take_output()) text.append(telegram.bytes.begin(), telegram.bytes.end());
    return text;
  }
};

TEST(RebEmulator, AnswersEachLineWithItsReplyThenThePrompt) {
  Session session;
  EXPECT_EQ(session.say("Y,0"), "y\r\n:\r\n");
  EXPECT_EQ(session.say("H,2"), "h,0\r\n:\r\n");
  EXPECT_EQ(session.say("I,15"), "i,360\r\n:\r\n");  // 7.2 V in 20 mV steps
  EXPECT_EQ(session.say("I,3"), "i,0\r\n:\r\n");
  EXPECT_EQ(session.say("A,0,1000,0,10"), "a\r\n:\r\n");
  EXPECT_EQ(session.say("F,2,100,0,10"), "f\r\n:\r\n");
  EXPECT_EQ(session.say("J,2,24,24"), "j\r\n:\r\n");
  EXPECT_EQ(session.say("Q,3,1"), "q\r\n:\r\n");
  EXPECT_EQ(session.say("E,0"), "e,0\r\n:\r\n");
  // Nonsense gets the prompt alone; a lone CR (1.5's restart) nothing.
  EXPECT_EQ(session.say("X,1"), ":\r\n");
  EXPECT_EQ(session.say(""), "");
}

TEST(RebEmulator, TakesItsTimeSoACycleLastsOver10ms) {
  Session session;
  EXPECT_EQ(session.say("H,2", 1ms), "");
  EXPECT_EQ(session.run(5ms), "h,0\r\n:\r\n");
  // Six round trips of a driver's cycle, each written when the last came.
  Duration start = session.now;
  for (const char* line : {"D,2,0", "D,0,0", "W", "I,15", "H,2", "H,0"}) {
    std::string heard = session.say(line, 0ms);
    while (heard.find(":\r\n") == std::string::npos) heard += session.run(100us);
  }
  EXPECT_GT(session.now - start, 10ms);
}

TEST(RebEmulator, SpeedsMoveTheCountersAndTheBody) {
  Session session;
  session.say("D,2,24");
  session.say("D,0,-24");  // the right motor runs negated forwards
  session.run(1s);
  session.say("D,2,0");
  session.say("D,0,0");
  const double pulses = session.board.motor(Motor::left).counter;
  EXPECT_NEAR(pulses, 2400.0 + 24.0, 60.0);  // ~1 s at 24 pulses / 10 ms
  EXPECT_NEAR(session.board.motor(Motor::right).counter, -pulses, 1.0);
  const double metres = pulses / 24.333022 / 1000.0;
  EXPECT_NEAR(session.board.drive().true_pose().x, metres, 0.002);
  EXPECT_NEAR(session.board.drive().true_pose().y, 0.0, 2e-3);  // the left wheel started 10 ms first
  EXPECT_EQ(session.say("H,2"), "h," + std::to_string(std::lround(pulses)) + "\r\n:\r\n");
  EXPECT_EQ(session.say("E,2"), "e,0\r\n:\r\n");
  session.say("G,2,-5");
  EXPECT_EQ(session.say("H,2"), "h,-5\r\n:\r\n");
}

TEST(RebEmulator, TurnsOnTheSpotWhenTheWheelsOppose) {
  Session session;
  session.say("D,2,-27");
  session.say("D,0,-27");
  session.run(1s);
  EXPECT_NEAR(session.board.drive().true_pose().yaw, 90.0 * 3.14159265 / 180.0, 0.1);
  EXPECT_NEAR(session.board.drive().true_pose().x, 0.0, 1e-3);
}

TEST(RebEmulator, DescribesItsWheelsAndTruePose) {
  // --stats shows what a driver's odometry is checked against (reference check, issue 29).
  Session session;
  session.say("D,2,-27");
  session.say("D,0,-27");
  session.run(1s);
  const std::string text = session.board.describe();
  EXPECT_NE(text.find("wheels -27/-27 pulses/10 ms"), std::string::npos) << text;
  const geometry::Pose2& pose = session.board.drive().true_pose();
  EXPECT_NEAR(pose.yaw * 180.0 / 3.14159265, 90.0, 6.0);
  char where[80];
  std::snprintf(where, sizeof where, ", at (%.2f, %.2f, %.0f deg)", pose.x, pose.y, pose.yaw * 180.0 / 3.14159265358979);
  EXPECT_NE(text.find(where), std::string::npos) << text;
}

TEST(RebEmulator, PositionMovesStopOnTarget) {
  Session session;
  session.say("J,2,24,24");
  session.say("J,0,24,24");
  session.say("C,2,1000");
  session.say("C,0,-1000");
  EXPECT_EQ(session.say("K,0").substr(0, 4), "k,0,");
  session.run(2s);
  EXPECT_EQ(session.say("K,0"), "k,1,1,0\r\n:\r\n");
  EXPECT_EQ(session.say("H,2"), "h,1000\r\n:\r\n");
  EXPECT_NEAR(session.board.drive().true_pose().x, 1000.0 / 24.333022 / 1000.0, 0.002);
  EXPECT_EQ(session.board.next_deadline(), Duration::max());  // at rest, nothing to do
}

TEST(RebEmulator, IrReadsNothingWhileOffOrWithNothingNear) {
  Session session;
  EXPECT_EQ(session.say("W"), "w,0,0,0,0,0,0,0,0\r\n:\r\n");
  session.say("Y,1");
  EXPECT_TRUE(session.board.ir_on());
  EXPECT_EQ(session.say("W"), "w,0,0,0,0,0,0,0,0\r\n:\r\n");  // no map: nothing in range
}

TEST(RebEmulator, IrSeesTheMapsWallsAndTheBodyStallsAgainstThem) {
  // Free space with a wall 0.2 m ahead of the robot.
  grid::OccupancyGrid map(100, 100, 0.01, Eigen::Vector2d(-0.5, -0.5), grid::CellState::free);
  for (int row = 0; row < 100; ++row) map.set(70, row, grid::CellState::occupied);
  RebEmulatorOptions options;
  options.map = &map;
  Session session(options);
  session.say("Y,1");
  // Sensor 0 sits 35 mm ahead: 165 mm from the wall, 250 mV m / 0.165 m in 4 mV steps.
  EXPECT_NEAR(session.board.ir_reading(0), 379, 3);
  EXPECT_EQ(session.board.ir_reading(4), 0);  // nothing behind within 0.8 m
  session.say("D,2,48");
  session.say("D,0,-48");
  session.run(3s);
  EXPECT_LT(session.board.drive().true_pose().x, 0.2 - 0.09 + 0.01);  // the body's 90 mm radius
  EXPECT_GT(session.board.ir_reading(0), 379);
}

}  // namespace reb_emulator_test
}  // namespace playerkit::emulators
