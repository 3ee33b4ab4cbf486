// The emulated ER1 on a simulated clock, fed what Player 1.5's er1_position
// sends (er1.md §2.1), byte for byte.
#include "families/er1/emulator/er1_emulator.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "families/er1/protocol/er1_commands.hpp"

namespace playerkit::emulators {
namespace {

namespace er1 = hardware::er1;
using er1::Bytes;
using Motor = er1::Motor;
using namespace std::chrono_literals;

struct Er1EmulatorTest : ::testing::Test {
  explicit Er1EmulatorTest(Er1EmulatorOptions options = {}) : robot(options) {}

  // Sends `command` and returns everything answered.
  Bytes send(const Bytes& command) {
    robot.receive(command, now, 230400);
    Bytes answer;
    for (const Telegram& telegram : robot.take_output()) {
      answer.insert(answer.end(), telegram.bytes.begin(), telegram.bytes.end());
    }
    return answer;
  }
  void send_all(const std::vector<Bytes>& commands) {
    for (const Bytes& command : commands) EXPECT_EQ(send(command).size(), er1::reply_length(command[3]));
  }
  std::int32_t read_count(Motor motor) { return *er1::position_count(send(er1::read_position(motor))); }
  // 1.5's SetVelocity from standstill, in mm/s, then its MotorSpeed.
  void set_velocity(double left, double right) {
    send_all(er1::speed_sequence(Motor::port0, -er1::speed_register(left), true));
    send_all(er1::speed_sequence(Motor::port1, er1::speed_register(right), true));
    send_all({er1::execute(Motor::port0), er1::execute(Motor::port1)});
    send_all({er1::command(Motor::port0, er1::opcode::read_status)});
  }
  void wait(Duration time) {
    now += time;
    robot.advance(now);
  }

  Er1Emulator robot;
  Duration now{0};
};

TEST_F(Er1EmulatorTest, AnswersEachCommandWithTheBytes15Reads) {
  EXPECT_EQ(send(er1::init(Motor::port0)), (Bytes{0x00, 0xA9, 0x34, 0x10, 0x00, 0x13}));
  EXPECT_EQ(send(er1::init(Motor::port1)).size(), 6u);
  send_all(er1::reset_sequence(Motor::port0));
  send_all(er1::reset_sequence(Motor::port1));
  EXPECT_EQ(send(er1::command(Motor::port0, er1::opcode::read_status)).size(), 4u);
  EXPECT_EQ(send(er1::command16(Motor::port1, er1::opcode::voltage, 1)).size(), 4u);
  EXPECT_EQ(send(er1::read_position(Motor::port1)), (Bytes{0x00, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(robot.inits(), 2u);
}

TEST_F(Er1EmulatorTest, TheBadChecksumOf15sAccl3IsAnsweredButNotObeyed) {
  const Bytes accl3{0x00, 0xF2, 0x00, 0x90, 0x00, 0x00, 0x00, 0x7A};
  EXPECT_EQ(send(accl3), (Bytes{0x01, 0xFF}));
  EXPECT_EQ(robot.bad_checksums(), 1u);
}

TEST_F(Er1EmulatorTest, ACommandSplitAcrossWritesOrBehindNoiseIsStillOne) {
  const Bytes command = er1::set_velocity(Motor::port1, 1000);
  EXPECT_TRUE(send(Bytes(command.begin(), command.begin() + 3)).empty());
  EXPECT_EQ(send(Bytes(command.begin() + 3, command.end())).size(), 2u);
  EXPECT_EQ(robot.latched_velocity(Motor::port1), 1000);
  Bytes noisy{0x55, 0xAA};
  const Bytes init = er1::init(Motor::port0);
  noisy.insert(noisy.end(), init.begin(), init.end());
  EXPECT_EQ(send(noisy).size(), 6u);
}

TEST_F(Er1EmulatorTest, AVelocityRunsFromItsExecuteAndTheCountsFollowTheWheels) {
  send_all(er1::speed_sequence(Motor::port0, -er1::speed_register(100), true));
  EXPECT_EQ(robot.latched_velocity(Motor::port0), -168198);
  EXPECT_EQ(robot.running_velocity(Motor::port0), 0);
  send_all(er1::speed_sequence(Motor::port1, er1::speed_register(100), true));
  send_all({er1::execute(Motor::port0), er1::execute(Motor::port1)});
  EXPECT_EQ(robot.running_velocity(Motor::port0), -168198);
  wait(2s);
  EXPECT_NEAR(robot.true_pose().x, 0.2, 1e-3);
  EXPECT_NEAR(robot.true_pose().y, 0.0, 1e-6);
  // v x 0.098623 ticks a second (er1.md §6.3); motor 0 counts down going forward.
  EXPECT_NEAR(read_count(Motor::port0), -2.0 * 168198 * 0.098623, 20);
  EXPECT_NEAR(read_count(Motor::port1), 2.0 * 168198 * 0.098623, 20);
}

TEST_F(Er1EmulatorTest, TurnsLeftWhenTheRightWheelIsFaster) {
  set_velocity(-100, 100);
  wait(1s);
  // 0.2 m/s between the wheels over a 0.38 m axle.
  EXPECT_NEAR(robot.true_pose().yaw, 0.2 / 0.38, 1e-3);
  EXPECT_NEAR(robot.true_pose().x, 0.0, 1e-6);
}

TEST_F(Er1EmulatorTest, TheStopSequenceStopsAndZeroesTheCount) {
  set_velocity(100, 100);
  wait(1s);
  send_all(er1::stop_sequence(Motor::port0));
  send_all(er1::stop_sequence(Motor::port1));
  EXPECT_FALSE(robot.moving());
  EXPECT_EQ(read_count(Motor::port0), 0);
  const double x = robot.true_pose().x;
  wait(1s);
  EXPECT_EQ(robot.true_pose().x, x);
  EXPECT_EQ(robot.next_deadline(), Duration::max());
}

struct Er1MirroredEmulatorTest : Er1EmulatorTest {
  static Er1EmulatorOptions left_motor_on_port1() {
    Er1EmulatorOptions options;
    options.left_motor_port = 1;
    return options;
  }
  Er1MirroredEmulatorTest() : Er1EmulatorTest(left_motor_on_port1()) {}
};

TEST_F(Er1MirroredEmulatorTest, WithTheLeftMotorOnPort1Port1IsTheMirroredOne) {
  send_all(er1::speed_sequence(Motor::port1, -er1::speed_register(100), true));  // left, forward
  send_all(er1::speed_sequence(Motor::port0, 0, true));
  send_all({er1::execute(Motor::port0), er1::execute(Motor::port1)});
  wait(1s);
  EXPECT_LT(robot.true_pose().yaw, -0.1);  // the left wheel alone turns it right
  EXPECT_LT(read_count(Motor::port1), 0);
  EXPECT_EQ(read_count(Motor::port0), 0);
}

TEST_F(Er1EmulatorTest, TheCountIsA32BitRegisterThatWraps) {
  set_velocity(1000, 1000);  // the drive clamps at 1 m/s
  wait(std::chrono::seconds(13000));  // 2^31 ticks is 12.9 km
  const std::int32_t count = read_count(Motor::port1);
  EXPECT_LT(count, 0);  // past 2^31
}

TEST(Er1EmulatorOptions, RefusesAnAxleOfNothingAndAThirdPort) {
  Er1EmulatorOptions no_axle;
  no_axle.axle = 0.0;
  EXPECT_THROW(Er1Emulator{no_axle}, std::invalid_argument);
  Er1EmulatorOptions third_port;
  third_port.left_motor_port = 2;
  EXPECT_THROW(Er1Emulator{third_port}, std::invalid_argument);
}

}  // namespace
}  // namespace playerkit::emulators
