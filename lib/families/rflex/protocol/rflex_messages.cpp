#include "families/rflex/protocol/rflex_messages.hpp"

namespace playerkit::hardware::rflex {

namespace {

// The reference sent sonar commands and DIO-off with id 4, everything else 0.
constexpr std::uint8_t kSonarCommandId = 4;

Packet plain(std::uint8_t port, std::uint8_t op, std::uint8_t id = 0) { return {port, id, op, {}}; }

bool is(const Packet& packet, std::uint8_t port, std::uint8_t op, std::size_t min_length) {
  return packet.port == port && packet.opcode == op && packet.data.size() >= min_length;
}

std::int32_t as_signed(std::uint32_t value) { return static_cast<std::int32_t>(value); }

}  // namespace

Packet motion_report_request(std::uint32_t period, std::uint32_t axis_mask) {
  Packet packet = plain(port::motion, opcode::mot_system_report_req);
  put_u32(packet.data, period);
  put_u32(packet.data, axis_mask);
  return packet;
}

Packet dio_reports_request(std::uint32_t period) {
  Packet packet = plain(port::dio, opcode::dio_reports_req, period == 0 ? kSonarCommandId : 0);
  put_u32(packet.data, period);
  return packet;
}

Packet set_defaults() { return plain(port::motion, opcode::mot_set_defaults); }
Packet brake_set() { return plain(port::motion, opcode::mot_brake_set); }
Packet brake_release() { return plain(port::motion, opcode::mot_brake_release); }
Packet system_status_request() { return plain(port::system, opcode::sys_status); }
Packet joystick_request() { return plain(port::joystick, opcode::jstk_get_state); }

Packet axis_set_direction(const AxisCommand& command) {
  Packet packet = plain(port::motion, opcode::mot_axis_set_dir);
  packet.data.push_back(command.axis);
  put_u32(packet.data, command.velocity);
  put_u32(packet.data, command.acceleration);
  put_u32(packet.data, command.torque);
  packet.data.push_back(command.positive ? 1 : 0);
  return packet;
}

std::optional<AxisCommand> read_axis_command(const Packet& packet) {
  if (!is(packet, port::motion, opcode::mot_axis_set_dir, 14)) return std::nullopt;
  return AxisCommand{packet.data[0], get_u32(packet.data, 1), get_u32(packet.data, 5), get_u32(packet.data, 9),
                     packet.data[13] != 0};
}

std::uint32_t avoid_escape_bytes(std::uint32_t velocity) {
  if (((velocity >> 8) & 0xFF) == kEscape) {
    // 0x..1Bxx lies between 0x..1AFF and 0x..1C00: take the nearer.
    const bool upper = (velocity & 0x80) != 0;
    velocity = (velocity & 0xFFFF0000U) | (upper ? 0x1C00U : 0x1AFFU);
  }
  if ((velocity >> 24) == kEscape) {
    const bool upper = (velocity & 0x00800000U) != 0;
    velocity = upper ? 0x1C000000U : 0x1AFFFFFFU;
  }
  return velocity;
}

Packet sonar_run(const SonarRun& run) {
  Packet packet = plain(port::sonar, opcode::sonar_run, kSonarCommandId);
  put_u32(packet.data, run.echo_delay);
  put_u32(packet.data, run.ping_delay);
  put_u32(packet.data, run.set_delay);
  packet.data.push_back(run.mode);
  return packet;
}

std::optional<SonarRun> read_sonar_run(const Packet& packet) {
  if (!is(packet, port::sonar, opcode::sonar_run, 13)) return std::nullopt;
  return SonarRun{get_u32(packet.data, 0), get_u32(packet.data, 4), get_u32(packet.data, 8), packet.data[12]};
}

Packet ir_run(bool on) {
  Packet packet = plain(port::ir, opcode::ir_run);
  for (const std::uint32_t field : {0U, 70U, 10U, 20U, 150U}) put_u32(packet.data, on ? field : 0U);
  packet.data.push_back(on ? kIrRunOn : 0);
  return packet;
}

std::optional<bool> read_ir_run(const Packet& packet) {
  if (!is(packet, port::ir, opcode::ir_run, 21)) return std::nullopt;
  return packet.data[20] != 0;
}

std::optional<ReportRequest> read_report_request(const Packet& packet) {
  if (is(packet, port::motion, opcode::mot_system_report_req, 8)) {
    return ReportRequest{get_u32(packet.data, 0), get_u32(packet.data, 4)};
  }
  if (is(packet, port::dio, opcode::dio_reports_req, 4)) return ReportRequest{get_u32(packet.data, 0), 0};
  return std::nullopt;
}

Packet motion_report(const MotionReport& report, std::uint8_t id) {
  Packet packet = plain(port::motion, opcode::mot_system_report, id);
  put_u32(packet.data, 0);  // rv
  put_u32(packet.data, report.timestamp);
  packet.data.push_back(report.axis);
  put_u32(packet.data, static_cast<std::uint32_t>(report.position));
  put_u32(packet.data, static_cast<std::uint32_t>(report.velocity));
  put_u32(packet.data, 0);  // acceleration
  put_u32(packet.data, 0);  // torque
  return packet;
}

std::optional<MotionReport> read_motion_report(const Packet& packet) {
  if (!is(packet, port::motion, opcode::mot_system_report, 25)) return std::nullopt;
  return MotionReport{get_u32(packet.data, 4), packet.data[8], as_signed(get_u32(packet.data, 9)),
                      as_signed(get_u32(packet.data, 13))};
}

Packet system_status(const SystemStatus& status, std::uint8_t id) {
  Packet packet = plain(port::system, opcode::sys_status, id);
  put_u32(packet.data, status.timestamp);
  put_u32(packet.data, status.voltage);
  packet.data.push_back(status.brake);
  return packet;
}

std::optional<SystemStatus> read_system_status(const Packet& packet) {
  if (!is(packet, port::system, opcode::sys_status, 9)) return std::nullopt;
  return SystemStatus{get_u32(packet.data, 0), get_u32(packet.data, 4), packet.data[8]};
}

Packet sonar_report(std::uint32_t timestamp, const std::vector<SonarEcho>& echoes, std::uint8_t id) {
  Packet packet = plain(port::sonar, opcode::sonar_report, id);
  put_u32(packet.data, 0);  // retval
  put_u32(packet.data, timestamp);
  for (const SonarEcho& echo : echoes) {
    packet.data.push_back(echo.id);
    put_u16(packet.data, echo.range);
  }
  return packet;
}

std::optional<std::vector<SonarEcho>> read_sonar_report(const Packet& packet) {
  if (!is(packet, port::sonar, opcode::sonar_report, 8)) return std::nullopt;
  std::vector<SonarEcho> echoes;
  for (std::size_t at = 8; at + 3 <= packet.data.size(); at += 3) {
    echoes.push_back({packet.data[at], get_u16(packet.data, at + 1)});
  }
  return echoes;
}

Packet dio_report(const DioReport& report, std::uint8_t id) {
  Packet packet = plain(port::dio, opcode::dio_report, id);
  put_u32(packet.data, report.timestamp);
  packet.data.push_back(report.address);
  put_u16(packet.data, report.value);
  return packet;
}

std::optional<DioReport> read_dio_report(const Packet& packet) {
  if (!is(packet, port::dio, opcode::dio_report, 7)) return std::nullopt;
  return DioReport{get_u32(packet.data, 0), packet.data[4], get_u16(packet.data, 5)};
}

Packet ir_report(std::uint32_t timestamp, const std::vector<IrBank>& banks, std::uint8_t id) {
  Packet packet = plain(port::ir, opcode::ir_report, id);
  packet.data.push_back(static_cast<std::uint8_t>(banks.size()));
  for (const IrBank& bank : banks) {
    put_u32(packet.data, timestamp);
    packet.data.insert(packet.data.end(), bank.begin(), bank.end());
    packet.data.push_back(0x80);  // reserved
  }
  return packet;
}

std::optional<std::vector<IrBank>> read_ir_report(const Packet& packet) {
  if (!is(packet, port::ir, opcode::ir_report, 1)) return std::nullopt;
  std::vector<IrBank> banks;
  for (std::size_t bank = 0; bank < packet.data[0]; ++bank) {
    const std::size_t at = 1 + 13 * bank + 4;
    if (at + 8 > packet.data.size()) break;  // fewer banks than it says: what came is used
    IrBank readings{};
    for (std::size_t j = 0; j < readings.size(); ++j) readings[j] = packet.data[at + j];
    banks.push_back(readings);
  }
  return banks;
}

Packet joystick_state(const JoystickState& state, std::uint8_t id) {
  Packet packet = plain(port::joystick, opcode::jstk_get_state, id);
  put_u32(packet.data, state.timestamp);
  put_u32(packet.data, static_cast<std::uint32_t>(state.x));
  put_u32(packet.data, static_cast<std::uint32_t>(state.y));
  packet.data.push_back(state.buttons);
  return packet;
}

std::optional<JoystickState> read_joystick_state(const Packet& packet) {
  if (!is(packet, port::joystick, opcode::jstk_get_state, 13)) return std::nullopt;
  return JoystickState{get_u32(packet.data, 0), as_signed(get_u32(packet.data, 4)), as_signed(get_u32(packet.data, 8)),
                       packet.data[12]};
}

}  // namespace playerkit::hardware::rflex
