// The SIP's other fields and the extra packets: battery, compass, digital
// and analog inputs, gripper, GYROPAC, SERAUX2, and the commands that are
// accepted and ignored.

#include "families/p2os/emulator/test_support.hpp"

#include "families/p2os/protocol/aux_serial.hpp"
#include "families/p2os/protocol/gripper.hpp"
#include "families/p2os/protocol/gyro_packet.hpp"

#include <numbers>

namespace playerkit::emulators {
namespace sensors_test {

using namespace testing;
namespace command = hw::command;
namespace gripper_command = hw::gripper_command;
namespace gripper_state = hw::gripper_state;
namespace gripper_beam = hw::gripper_beam;
using hw::Command;

hw::StandardSip next_sip(Host& host) {
  host.take_frames();
  host.wait(100ms);
  auto sips = host.take_sips();
  EXPECT_EQ(sips.size(), 1u);
  return sips.empty() ? hw::StandardSip{} : sips.back();
}

TEST(P2osSensors, BatteryCompassAndInputs) {
  P2osEmulatorOptions options;
  options.battery_volts = 12.46;
  options.initial_pose = {0.0, 0.0, std::numbers::pi / 2};
  options.analog_input = 77;
  options.analog_port = 5;
  options.digital_inputs = 0xC0;
  P2osRobotEmulator robot(options);
  Host host(robot);
  host.connect();
  hw::StandardSip sip = next_sip(host);
  EXPECT_EQ(sip.battery, 125);
  EXPECT_EQ(sip.compass, 46) << "90 degrees";
  EXPECT_EQ(sip.analog, 77);
  EXPECT_EQ(sip.analog_port, 5);
  EXPECT_EQ(sip.digital_in & 0xC0, 0xC0);
  EXPECT_EQ(sip.digital_out, 0);

  robot.set_battery_volts(11.0);
  robot.set_analog_input(3);
  robot.set_digital_inputs(0x40);
  robot.set_true_pose({0.0, 0.0, -std::numbers::pi / 2});
  sip = next_sip(host);
  EXPECT_EQ(sip.battery, 110);
  EXPECT_EQ(hw::compass_degrees(sip.compass), 270);
  EXPECT_EQ(sip.analog, 3);
  EXPECT_EQ(sip.digital_in & 0xC0, 0x40);
  EXPECT_EQ(robot.odometry_pose(), geometry::Pose2{}) << "moving the robot by hand is not odometry";
}

TEST(P2osSensors, WithoutAGripperDiginIsTheInputs) {
  P2osEmulatorOptions options;
  options.has_gripper = false;
  options.digital_inputs = 0x5A;
  P2osRobotEmulator robot(options);
  Host host(robot);
  host.connect();
  host.send(command::gripper, gripper_command::open);
  const hw::StandardSip sip = next_sip(host);
  EXPECT_EQ(sip.digital_in, 0x5A);
  EXPECT_EQ(sip.gripper_state, 0);
}

TEST(P2osSensors, GripperPaddlesAndLiftMoveOverTheirTravelTime) {
  P2osRobotEmulator robot;  // travel 1.5 s; starts stored: closed and up
  Host host(robot);
  host.connect();
  hw::StandardSip sip = next_sip(host);
  EXPECT_EQ(sip.gripper_state, gripper_state::paddles_closed | gripper_state::lift_up);

  // What the 1.5 driver sends first: GRIPstore (quirk 10), already there.
  host.send(command::gripper, gripper_command::store);
  EXPECT_EQ(next_sip(host).gripper_state, gripper_state::paddles_closed | gripper_state::lift_up);

  host.send(command::gripper, gripper_command::deploy);
  sip = next_sip(host);
  EXPECT_EQ(sip.gripper_state, gripper_state::paddles_moving | gripper_state::lift_moving);
  EXPECT_EQ(sip.digital_in & (gripper_beam::gripper_limit | gripper_beam::lift_limit), 0);
  host.wait(1200ms);
  EXPECT_TRUE(next_sip(host).gripper_state & gripper_state::paddles_moving) << "still moving at 1.3 s";
  host.wait(200ms);
  sip = next_sip(host);
  EXPECT_EQ(sip.gripper_state, gripper_state::paddles_open | gripper_state::lift_down);
  EXPECT_EQ(sip.digital_in & 0x3F, gripper_beam::gripper_limit | gripper_beam::lift_limit |
                                        gripper_beam::left_paddle_open |
                                        gripper_beam::right_paddle_open);

  host.send(command::gripper, gripper_command::close);
  host.wait(500ms);
  host.send(command::gripper, gripper_command::stop);
  sip = next_sip(host);
  EXPECT_EQ(sip.gripper_state & 0x0F, 0) << "stopped half way: neither open, closed nor moving";
  EXPECT_NEAR(robot.gripper().paddle_opening(), 1.0 - 0.5 / 1.5, 1e-9);

  host.send(command::gripper, gripper_command::press);
  host.send(command::gripper_value, 100);  // the pressure: accepted, not modelled
  host.send(command::gripper, gripper_command::lift_up);
  host.wait(2s);
  EXPECT_EQ(next_sip(host).gripper_state, gripper_state::paddles_closed | gripper_state::lift_up);

  robot.set_gripper_beams(true, true);
  EXPECT_EQ(next_sip(host).digital_in & (gripper_beam::outer_beam | gripper_beam::inner_beam),
            gripper_beam::outer_beam | gripper_beam::inner_beam);
}

TEST(P2osSensors, GyroPacketPrecedesEachSipOnceRequested) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.send(command::enable, 1);
  host.wait(300ms);
  for (const auto& packet : host.take_packets()) EXPECT_NE(packet[0], hw::packet_type::gyro);

  host.send(command::gyro, 1);
  EXPECT_TRUE(robot.gyro_enabled());
  host.wait(300ms);
  auto packets = host.take_packets();
  ASSERT_EQ(packets.size(), 6u);
  for (std::size_t i = 0; i < packets.size(); i += 2) {
    EXPECT_EQ(packets[i][0], hw::packet_type::gyro);
    EXPECT_TRUE(hw::is_standard_sip(packets[i + 1][0]));
    EXPECT_EQ(hw::decode_gyro_packet(packets[i]).average_rate(), 512) << "no rotation";
  }

  host.keep_sending(Command::with_integer(command::rvel, 45), 500ms);
  packets = host.take_packets();
  ASSERT_GE(packets.size(), 2u);
  const auto gyro = hw::decode_gyro_packet(packets[packets.size() - 2]);
  // Counter-clockwise reads below 512: 45°/s over the p3dx GyroScaler 1.626.
  EXPECT_EQ(gyro.average_rate(), 512 - 28);

  host.send(command::gyro, 0);
  host.wait(300ms);
  for (const auto& packet : host.take_packets()) EXPECT_NE(packet[0], hw::packet_type::gyro);
}

TEST(P2osSensors, Getaux2AnswersWithOneCmucamMessage) {
  P2osEmulatorOptions options;
  options.cmucam_blob = hw::CmucamTracking{.mx = 40, .my = 70, .x1 = 30, .y1 = 60, .x2 = 50,
                                           .y2 = 80, .pixels = 90, .confidence = 200};
  P2osRobotEmulator robot(options);
  Host host(robot);
  host.connect();
  host.send(Command::with_string(command::tty3, "\r"));
  host.send(command::getaux2, 0);
  EXPECT_TRUE(host.take_frames().empty()) << "GETAUX2 0 only flushes";
  host.send(command::getaux2, 19);
  const auto packets = host.take_packets();
  ASSERT_EQ(packets.size(), 1u);
  const hw::AuxSerialPacket aux = hw::decode_aux_serial(packets[0]);
  EXPECT_EQ(aux.type, hw::packet_type::serial_aux2);
  EXPECT_EQ(aux.data.size(), 10u);
  EXPECT_EQ(hw::find_cmucam_message(aux.data), hw::CmucamMessage(*options.cmucam_blob));

  P2osEmulatorOptions blind;
  blind.has_cmucam = false;
  P2osRobotEmulator no_camera(blind);
  Host other(no_camera);
  other.connect();
  other.send(command::getaux2, 19);
  EXPECT_TRUE(other.take_frames().empty());
}

TEST(P2osSensors, SoundJoydriveAndPulseAreAcceptedAndIgnored) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.write(hex("FA FB 06 5A 3B 55 72 AF AD"));  // SOUND 0x7255, as the reference sends it
  host.send(command::joydrive, 1);
  host.send(command::pulse);
  EXPECT_TRUE(host.take_frames().empty());
  EXPECT_TRUE(robot.connected());
  EXPECT_EQ(robot.packets_received(command::sound), 1u);
  EXPECT_EQ(robot.packets_received(command::joydrive), 1u);
  EXPECT_EQ(robot.counters().ignored, 0u);
  host.wait(100ms);
  EXPECT_EQ(host.take_sips().size(), 1u);
}

}  // namespace sensors_test
}  // namespace playerkit::emulators
