#include "families/er1/driver/er1_rcm.hpp"

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>

namespace playerkit::drivers::er1 {

namespace {

constexpr rcm::Motor kBothMotors[] = {rcm::Motor::port0, rcm::Motor::port1};

const char* opcode_name(std::uint8_t op) {
  switch (op) {
    case rcm::opcode::init: return "INIT";
    case rcm::opcode::reset_position: return "RESET";
    case rcm::opcode::execute: return "EXECUTE";
    case rcm::opcode::read_position: return "position";
    case rcm::opcode::read_status: return "status";
    case rcm::opcode::velocity: return "velocity";
    case rcm::opcode::acceleration: return "acceleration";
    default: return "setting";
  }
}

std::string command_name(const rcm::Bytes& command) {
  char name[48];
  std::snprintf(name, sizeof name, "%s (opcode 0x%02X) to motor %d", opcode_name(command[3]), command[3], command[0]);
  return name;
}

}  // namespace

Rcm::Rcm(links::ByteLink& link, Wiring wiring, std::function<bool()> stopping)
    : wiring_(wiring),
      reader_(link, format_, rcm::ReplyFormat::kLongest),
      exchanger_(reader_, std::move(stopping), "the ER1's motor controller") {}

rcm::Bytes Rcm::ask(const rcm::Bytes& command) {
  format_.expect(rcm::reply_length(command[3]));
  // The RCM says nothing unasked, so bytes behind a reply mean it was cut
  // from noise in front of the real one: wait for that instead.
  const auto ends_the_input = [this](std::span<const std::uint8_t> /*telegram*/) {
    return reader_.buffered() == 0 ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
  };
  return exchanger_.exchange({.name = command_name(command),
                              .bytes = command,
                              .matcher = ends_the_input,
                              .timeout = kReplyTimeout,
                              .attempts = kAttempts});
}

void Rcm::send_all(const std::vector<rcm::Bytes>& commands) {
  for (const rcm::Bytes& command : commands) (void)ask(command);
}

void Rcm::start() {
  for (const rcm::Motor motor : kBothMotors) (void)ask(rcm::init(motor));
  for (const rcm::Motor motor : kBothMotors) {
    (void)ask(rcm::init(motor));
    send_all(rcm::reset_sequence(motor));
  }
  standing_ = true;
}

void Rcm::drive(const WheelSpeeds& wheels) {
  for (const rcm::Motor motor : kBothMotors) {
    const std::int32_t speed = motor == wiring_.left ? -rcm::speed_register(wheels.left)
                                                     : rcm::speed_register(wheels.right);
    send_all(rcm::speed_sequence(motor, speed, standing_));
  }
  send_all({rcm::execute(rcm::Motor::port0), rcm::execute(rcm::Motor::port1)});
  for (const rcm::Motor motor : kBothMotors) send_all(rcm::acceleration_sequence(motor));
  send_all({rcm::execute(rcm::Motor::port0), rcm::execute(rcm::Motor::port1)});
  standing_ = wheels.left == 0.0 && wheels.right == 0.0;
}

std::int32_t Rcm::count(rcm::Motor motor) {
  const auto value = rcm::position_count(ask(rcm::read_position(motor)));
  return value.value_or(0);  // the format only passes 6-byte replies
}

WheelCounts Rcm::counts() {
  std::int32_t port0 = count(rcm::Motor::port0);
  const auto between = std::chrono::steady_clock::now();
  const std::int32_t port1 = count(rcm::Motor::port1);
  // Counts read far apart in time (a reply asked for again) make a robot
  // driving straight seem to turn and turn back, and the pose drifts
  // sideways: port 0 is read again, right after port 1.
  if (std::chrono::steady_clock::now() - between > kCountSkew) port0 = count(rcm::Motor::port0);
  const std::int32_t left = wiring_.left == rcm::Motor::port0 ? port0 : port1;
  const std::int32_t right = wiring_.left == rcm::Motor::port0 ? port1 : port0;
  return {.left = static_cast<std::int32_t>(0u - static_cast<std::uint32_t>(left)), .right = right};
}

void Rcm::stop() {
  for (const rcm::Motor motor : kBothMotors) send_all(rcm::stop_sequence(motor));
  standing_ = true;
  drive({});
}

}  // namespace playerkit::drivers::er1
