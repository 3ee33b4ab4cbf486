#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/gripper.hpp"

namespace playerkit::drivers::sim {

namespace {

// The Pioneer gripper command set (Player 1.5 manual, gripper interface).
enum PioneerGripperCommand : std::uint8_t {
  kGripOpen = 1,
  kGripClose = 2,
  kGripStore = 7,   // close and lift
  kGripDeploy = 8,  // lower and open
};

// The Pioneer gripper's bits, as 1.5's p2os and gz_gripper reported them.
constexpr std::uint8_t kStateOpen = 0x01;
constexpr std::uint8_t kStateClosed = 0x02;
constexpr std::uint8_t kStateMoving = 0x04;
constexpr std::uint8_t kBeamOuter = 0x04;
constexpr std::uint8_t kBeamInner = 0x08;
constexpr std::uint8_t kBeamPaddlesOpen = 0x10 | 0x20;  // left and right paddle open

}  // namespace

void SimGripperDriver::apply_command(World& world, const core::Command& command) {
  const auto wanted = decode_padded<protocol::GripperCommand>(command.payload);
  switch (wanted.cmd) {
    case kGripOpen:
    case kGripDeploy:
      world.open_gripper(model());
      break;
    case kGripClose:
    case kGripStore:
      world.close_gripper(model());
      break;
    default:
      break;  // lift, stop, press: the simulated gripper has no lift and never halts midway
  }
}

double SimGripperDriver::reading_time(const World& world) const { return world.gripper(model()).time; }

std::optional<std::vector<std::uint8_t>> SimGripperDriver::encode_reading(const World& world) {
  const playerkit::sim::GripperReading& reading = world.gripper(model());
  protocol::GripperData data;
  switch (reading.paddles) {
    case playerkit::sim::GripperPaddles::open:
      data.state = kStateOpen;
      data.beams = kBeamPaddlesOpen;
      break;
    case playerkit::sim::GripperPaddles::closed:
      data.state = kStateClosed;
      break;
    case playerkit::sim::GripperPaddles::moving:
      data.state = kStateMoving;
      break;
  }
  if (reading.outer_beam) data.beams |= kBeamOuter;
  if (reading.inner_beam) data.beams |= kBeamInner;
  return protocol::encode(data);
}

}  // namespace playerkit::drivers::sim
