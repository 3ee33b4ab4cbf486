// The 1.5 driver's own pacing (p2os.md §2.4), replayed against the
// emulator: the handshake with its sleeps, then "every transmission paired
// with exactly one reception". If the robot answered too little, too late
// or out of turn, this host would block or misparse, as the reference would.

#include "families/p2os/emulator/test_support.hpp"

#include <deque>
#include <numbers>

namespace playerkit::emulators {
namespace reference_session_test {

using namespace testing;
namespace command = hw::command;
using hw::Command;

class ReferenceDriver {
 public:
  explicit ReferenceDriver(P2osRobotEmulator& robot) : robot_(robot), host_(robot) {}

  void sleep(Duration span) {
    host_.wait(span);
    for (auto& packet : host_.take_packets()) inbox_.push_back(std::move(packet));
  }

  // The blocking read: waits for the next whole packet (bounded here).
  std::vector<std::uint8_t> read_packet() {
    for (int ms = 0; inbox_.empty() && ms < 10'000; ++ms) sleep(1ms);
    EXPECT_FALSE(inbox_.empty()) << "the reference would block forever here";
    if (inbox_.empty()) return {0xFF};
    auto packet = std::move(inbox_.front());
    inbox_.pop_front();
    handle(packet);
    return packet;
  }

  // Write one command, then consume exactly one packet.
  std::vector<std::uint8_t> transact(const Command& c) {
    host_.send(c);
    return read_packet();
  }

  // Steps 3-9 of §2.4.
  void start_up(bool with_gyro) {
    host_.send(command::sync0);
    sleep(400ms);
    ASSERT_FALSE(inbox_.empty()) << "SYNC0 echo within 400 ms";
    EXPECT_EQ(read_packet(), hex("00"));
    sleep(200ms);
    host_.send(command::sync1);
    sleep(200ms);
    EXPECT_EQ(read_packet(), hex("01"));
    sleep(200ms);
    host_.send(command::sync2);
    sleep(200ms);
    const hw::Sync2Reply reply = hw::decode_sync2_reply(read_packet());
    sleep(200ms);
    host_.send(command::open);
    sleep(200ms);
    host_.send(command::pulse);
    sleep(200ms);
    params_ = &hw::select_robot_params(reply.robot_class, reply.subclass);
    EXPECT_TRUE(hw::is_standard_sip(read_packet()[0]));
    transact(Command::with_integer(command::sonar, 0));
    if (with_gyro) transact(Command::with_integer(command::gyro, 1));
  }

  // Direct wheel mode as §3.1 computes it, clamped at 500 mm/s.
  Command vel2_for(double xspeed, double yawspeed) const {
    const double r = yawspeed * std::numbers::pi / 180.0 / params_->diff_conv_factor;
    const double left = std::clamp(xspeed - r, -500.0, 500.0);
    const double right = std::clamp(xspeed + r, -500.0, 500.0);
    const auto unit = [&](double v) { return static_cast<std::int8_t>(v / params_->vel2_divisor); };
    return Command::with_integer(command::vel2, hw::encode_vel2({unit(left), unit(right)}));
  }

  Duration now() const { return host_.now(); }
  double x_mm() const { return x_; }
  double y_mm() const { return y_; }
  int yaw_degrees() const { return yaw_; }
  int gyro_packets() const { return gyro_packets_; }
  int sips() const { return sips_; }

 private:
  // §3.1: integrated 12-bit odometry, first SIP sets 0, steps > 100 mm dropped.
  void handle(const std::vector<std::uint8_t>& packet) {
    if (packet[0] == hw::packet_type::gyro) {
      ++gyro_packets_;
      EXPECT_TRUE(hw::is_standard_sip(read_packet()[0])) << "a SIP follows each GYROPAC";
      return;
    }
    if (!hw::is_standard_sip(packet[0]) || params_ == nullptr) return;
    const hw::StandardSip sip = hw::decode_sip(packet);
    if (sips_++ > 0) {
      const double dx = std::rint(wrapped_difference(sip.x_position, last_x_) * params_->dist_conv_factor);
      const double dy = std::rint(wrapped_difference(sip.y_position, last_y_) * params_->dist_conv_factor);
      EXPECT_LE(std::abs(dx), 100.0);
      EXPECT_LE(std::abs(dy), 100.0);
      x_ += dx;
      y_ += dy;
    }
    last_x_ = sip.x_position;
    last_y_ = sip.y_position;
    yaw_ = static_cast<int>(std::rint(sip.heading * params_->angle_conv_factor * 180.0 / std::numbers::pi));
  }

  P2osRobotEmulator& robot_;
  Host host_;
  std::deque<std::vector<std::uint8_t>> inbox_;
  const hw::RobotParams* params_ = nullptr;
  double x_ = 0.0, y_ = 0.0;
  int yaw_ = 0;
  int sips_ = 0;
  int gyro_packets_ = 0;
  std::uint16_t last_x_ = 0, last_y_ = 0;
};

TEST(P2osReferenceSession, TheReferencePacingConnectsDrivesAndStaysInStep) {
  P2osRobotEmulator robot;
  ReferenceDriver driver(robot);
  driver.start_up(/*with_gyro=*/true);
  ASSERT_TRUE(robot.connected());
  EXPECT_FALSE(robot.sonar_enabled());
  EXPECT_TRUE(robot.gyro_enabled());

  // First loop with position and sonar subscribed (§2.4 loop, quirks 9, 10, 16).
  driver.transact(Command::with_integer(command::sonar, 1));
  driver.transact(Command::with_integer(command::enable, 0));
  driver.transact(Command::type_only(command::seto));
  driver.transact(driver.vel2_for(0, 0));
  driver.transact(Command::with_integer(command::gripper, 7));
  driver.transact(Command::with_integer(command::sound, 0x7255));
  // The client asks for MOTOR_POWER 1, then drives 300 mm/s straight for 2 s
  // and turns at 20°/s for 3 s.
  driver.transact(Command::with_integer(command::enable, 1));
  const Duration start = driver.now();
  for (int cycle = 0; cycle < 20; ++cycle) driver.transact(driver.vel2_for(300, 0));
  for (int cycle = 0; cycle < 30; ++cycle) driver.transact(driver.vel2_for(0, 20));
  driver.transact(driver.vel2_for(0, 0));
  driver.transact(driver.vel2_for(0, 0));

  // One SIP per command: the loop ran at the robot's 10 Hz.
  const double elapsed = std::chrono::duration<double>(driver.now() - start).count();
  EXPECT_NEAR(elapsed, 5.2, 0.15);
  EXPECT_GT(driver.gyro_packets(), 50);
  EXPECT_EQ(robot.packets_received(command::vel2), 53u);

  // The driver's view matches the world within its integer-mm rounding.
  EXPECT_NEAR(driver.x_mm(), robot.true_pose().x * 1000.0, 10.0);
  EXPECT_NEAR(driver.y_mm(), robot.true_pose().y * 1000.0, 10.0);
  EXPECT_NEAR(robot.true_pose().x, 0.6, 0.035);  // 2 s at 300 mm/s, give or take a cycle
  // VEL2 20°/s: right − left = 2 × trunc(62.3 / 20) × 20 = 120 mm/s.
  const double turn_rate = 120.0 * 0.0056 / 2.0 * 180.0 / std::numbers::pi;
  EXPECT_NEAR(driver.yaw_degrees(), turn_rate * 3.0, turn_rate * 0.15);
  EXPECT_EQ(robot.counters().bad_checksums, 0u);
  EXPECT_EQ(robot.counters().undecodable, 0u);
}

TEST(P2osReferenceSession, ShutdownStopsTheRobotAndTheNextStartUpWorks) {
  P2osRobotEmulator robot;
  ReferenceDriver driver(robot);
  driver.start_up(false);
  driver.transact(Command::with_integer(command::enable, 1));
  for (int cycle = 0; cycle < 5; ++cycle) driver.transact(driver.vel2_for(200, 0));
  // §2.4 shutdown: STOP, 200 ms, CLOSE, 200 ms, close the port.
  ReferenceDriver& d = driver;
  d.transact(Command::plain(command::stop));
  EXPECT_EQ(robot.wheel_velocities(), (mobile_base::WheelVelocities{0.0, 0.0}));
  d.sleep(200ms);
  robot.receive(hw::command_frame(Command::plain(command::close)), d.now(), 0);
  d.sleep(200ms);
  robot.host_disconnected(d.now());
  EXPECT_FALSE(robot.connected());
  d.sleep(1s);

  ReferenceDriver again(robot);
  again.sleep(d.now());  // same clock, later
  again.start_up(false);
  EXPECT_TRUE(robot.connected());
}

}  // namespace reference_session_test
}  // namespace playerkit::emulators
