#include "families/p2os/emulator/gripper_model.hpp"

#include "families/p2os/protocol/gripper.hpp"

#include <algorithm>

namespace playerkit::emulators::p2os {

namespace gripper_command = hardware::p2os::gripper_command;
namespace gripper_state = hardware::p2os::gripper_state;
namespace gripper_beam = hardware::p2os::gripper_beam;

GripperModel::GripperModel(double travel_seconds)
    : travel_seconds_(travel_seconds > 0.0 ? travel_seconds : 1.0) {}

// A direction that would push past the end already reached is no motion.
int GripperModel::towards(double position, int direction) {
  if (direction > 0 && position >= 1.0) return 0;
  if (direction < 0 && position <= 0.0) return 0;
  return direction;
}

void GripperModel::command(int gripper_command) {
  int paddles = paddle_direction_;
  int lift = lift_direction_;
  switch (gripper_command) {
    case gripper_command::open: paddles = +1; break;
    case gripper_command::close:
    case gripper_command::press: paddles = -1; break;
    case gripper_command::stop: paddles = 0; break;
    case gripper_command::lift_up:
    case gripper_command::lift_carry: lift = +1; break;
    case gripper_command::lift_down: lift = -1; break;
    case gripper_command::lift_stop: lift = 0; break;
    case gripper_command::store: paddles = -1; lift = +1; break;
    case gripper_command::deploy: paddles = +1; lift = -1; break;
    case gripper_command::halt: paddles = 0; lift = 0; break;
    default: return;
  }
  paddle_direction_ = towards(paddles_, paddles);
  lift_direction_ = towards(lift_, lift);
}

void GripperModel::move(double& position, int& direction, double amount) {
  if (direction == 0) return;
  position = std::clamp(position + direction * amount, 0.0, 1.0);
  direction = towards(position, direction);
}

void GripperModel::run(double seconds) {
  if (!(seconds > 0.0)) return;
  const double amount = seconds / travel_seconds_;
  move(paddles_, paddle_direction_, amount);
  move(lift_, lift_direction_, amount);
}

std::uint8_t GripperModel::state_bits() const {
  std::uint8_t bits = 0;
  if (paddle_direction_ != 0) bits |= gripper_state::paddles_moving;
  else if (paddles_ >= 1.0) bits |= gripper_state::paddles_open;
  else if (paddles_ <= 0.0) bits |= gripper_state::paddles_closed;
  if (lift_direction_ != 0) bits |= gripper_state::lift_moving;
  else if (lift_ >= 1.0) bits |= gripper_state::lift_up;
  else if (lift_ <= 0.0) bits |= gripper_state::lift_down;
  return bits;
}

std::uint8_t GripperModel::beam_bits() const {
  std::uint8_t bits = 0;
  if (paddles_ <= 0.0 || paddles_ >= 1.0) bits |= gripper_beam::gripper_limit;
  if (lift_ <= 0.0 || lift_ >= 1.0) bits |= gripper_beam::lift_limit;
  if (outer_beam_) bits |= gripper_beam::outer_beam;
  if (inner_beam_) bits |= gripper_beam::inner_beam;
  if (paddles_ >= 1.0) bits |= gripper_beam::left_paddle_open | gripper_beam::right_paddle_open;
  return bits;
}

void GripperModel::set_beams(bool outer_obstructed, bool inner_obstructed) {
  outer_beam_ = outer_obstructed;
  inner_beam_ = inner_obstructed;
}

}  // namespace playerkit::emulators::p2os
