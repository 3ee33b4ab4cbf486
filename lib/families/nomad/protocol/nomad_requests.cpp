#include "families/nomad/protocol/nomad_requests.hpp"

namespace playerkit::hardware::nomad {

namespace t = message_type;

Message connect_robot(std::int32_t client_pid) { return {t::kConnectRobot, {kRobotId, client_pid}}; }

Message sensor_mask() { return {t::kSensorMask, {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x0E, 0x00}}; }

Message command_timeout(std::int32_t seconds) { return {t::kCommandTimeout, {seconds}}; }

Message zero() { return {t::kZero, {}}; }

Message accelerations(const std::array<std::int32_t, 3>& tenths) {
  return {t::kAccelerations, {tenths.begin(), tenths.end()}};
}

Message speeds(const std::array<std::int32_t, 3>& tenths) { return {t::kSpeeds, {tenths.begin(), tenths.end()}}; }

Message velocity(std::int32_t translation, std::int32_t steering, std::int32_t turret) {
  return {t::kVelocityMode, {translation, steering, turret}};
}

Message get_state() { return {t::kGetState, {}}; }

Message state_reply(const RobotState& state) {
  Message reply{t::kState, {}};
  auto& w = reply.words;
  w.reserve(kStateWords + state.laser_points.size());
  w.push_back(state.simulation_speed);
  w.insert(w.end(), state.ir.begin(), state.ir.end());
  w.insert(w.end(), state.sonar.begin(), state.sonar.end());
  for (const std::int32_t value :
       {state.bumpers, state.x, state.y, state.steering, state.turret, state.translation_velocity,
        state.steering_velocity, state.turret_velocity, state.motor_status, state.laser_mode, state.compass,
        state.error}) {
    w.push_back(value);
  }
  w.push_back(static_cast<std::int32_t>(state.laser_points.size() / 2));
  w.insert(w.end(), state.laser_points.begin(), state.laser_points.end());
  w.push_back(state.controller_time);
  w.push_back(state.cpu_voltage);
  w.push_back(state.motor_voltage);
  return reply;
}

std::optional<RobotState> parse_state(const Message& message) {
  const auto& w = message.words;
  if (message.type != t::kState || w.size() < kStateWords) return std::nullopt;
  const std::int32_t points = w[45];
  if (points < 0 || w.size() < kStateWords + 2 * static_cast<std::size_t>(points)) return std::nullopt;
  RobotState state;
  state.simulation_speed = w[0];
  for (std::size_t i = 0; i < kIrCount; ++i) state.ir[i] = w[1 + i];
  for (std::size_t i = 0; i < kSonarCount; ++i) state.sonar[i] = w[17 + i];
  state.bumpers = w[33];
  state.x = w[34];
  state.y = w[35];
  state.steering = w[36];
  state.turret = w[37];
  state.translation_velocity = w[38];
  state.steering_velocity = w[39];
  state.turret_velocity = w[40];
  state.motor_status = w[41];
  state.laser_mode = w[42];
  state.compass = w[43];
  state.error = w[44];
  const std::size_t after_points = 46 + 2 * static_cast<std::size_t>(points);
  state.laser_points.assign(w.begin() + 46, w.begin() + static_cast<std::ptrdiff_t>(after_points));
  state.controller_time = w[after_points];
  state.cpu_voltage = w[after_points + 1];
  state.motor_voltage = w[after_points + 2];
  return state;
}

bool is_failure(const Message& reply) { return reply.type == t::kError || reply.type == t::kFailure; }

}  // namespace playerkit::hardware::nomad
