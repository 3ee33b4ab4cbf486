#pragma once
// What the host sends an RFLEX controller and what it reports (rflex.md §2),
// as packets: built for the side that sends them, read by the side that
// receives them (the driver reads reports, the emulator reads commands).
// Values are the controller's own units; conversions are the driver's.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "families/rflex/protocol/rflex_packet.hpp"

namespace playerkit::hardware::rflex {

namespace port {
inline constexpr std::uint8_t system = 1;
inline constexpr std::uint8_t motion = 2;
inline constexpr std::uint8_t joystick = 3;
inline constexpr std::uint8_t sonar = 4;
inline constexpr std::uint8_t dio = 5;
inline constexpr std::uint8_t ir = 6;
}  // namespace port

namespace opcode {
inline constexpr std::uint8_t sys_lcd_dump = 0;
inline constexpr std::uint8_t sys_status = 1;
inline constexpr std::uint8_t mot_axis_set_dir = 7;
inline constexpr std::uint8_t mot_set_defaults = 10;
inline constexpr std::uint8_t mot_brake_set = 11;
inline constexpr std::uint8_t mot_brake_release = 12;
inline constexpr std::uint8_t mot_system_report = 33;
inline constexpr std::uint8_t mot_system_report_req = 34;
inline constexpr std::uint8_t jstk_get_state = 0;
inline constexpr std::uint8_t sonar_run = 0;
inline constexpr std::uint8_t sonar_report = 2;
inline constexpr std::uint8_t dio_reports_req = 0;
inline constexpr std::uint8_t dio_report = 1;
inline constexpr std::uint8_t ir_run = 0;
inline constexpr std::uint8_t ir_report = 1;
}  // namespace opcode

inline constexpr std::uint8_t kTranslationAxis = 0;
inline constexpr std::uint8_t kRotationAxis = 1;
inline constexpr std::uint8_t kSonarRunOn = 2;
inline constexpr std::uint8_t kIrRunOn = 2;

// --- host -> robot

// Motion reports every `period` µs for the axes in `axis_mask` (bit 0 translation).
[[nodiscard]] Packet motion_report_request(std::uint32_t period, std::uint32_t axis_mask);
[[nodiscard]] Packet dio_reports_request(std::uint32_t period);
[[nodiscard]] Packet set_defaults();
[[nodiscard]] Packet brake_set();
[[nodiscard]] Packet brake_release();
[[nodiscard]] Packet system_status_request();
[[nodiscard]] Packet joystick_request();

struct AxisCommand {
  std::uint8_t axis = kTranslationAxis;
  std::uint32_t velocity = 0;  // magnitude, arb/s
  std::uint32_t acceleration = 0;
  std::uint32_t torque = 0;
  bool positive = true;
  friend bool operator==(const AxisCommand&, const AxisCommand&) = default;
};
[[nodiscard]] Packet axis_set_direction(const AxisCommand& command);
[[nodiscard]] std::optional<AxisCommand> read_axis_command(const Packet& packet);

// The controller's framing tolerates 0x1B inside data (the length byte
// rules), but the reference nudged any velocity byte 8-15 or 24-31 equal to
// 0x1B to the nearest value without it, fearing the controller's parser;
// the nearest value is kept here (1.5 chose by the lowest bit, §2.1).
[[nodiscard]] std::uint32_t avoid_escape_bytes(std::uint32_t velocity);

struct SonarRun {
  std::uint32_t echo_delay = 30000;  // µs
  std::uint32_t ping_delay = 0;
  std::uint32_t set_delay = 0;
  std::uint8_t mode = kSonarRunOn;  // 0 stops
  friend bool operator==(const SonarRun&, const SonarRun&) = default;
};
[[nodiscard]] Packet sonar_run(const SonarRun& run);
[[nodiscard]] std::optional<SonarRun> read_sonar_run(const Packet& packet);

// The reference's fixed IR timing (0, 70, 10, 20, 150, run 2); off is all zero.
[[nodiscard]] Packet ir_run(bool on);
// True for on, false for off, nullopt for not an IR_RUN.
[[nodiscard]] std::optional<bool> read_ir_run(const Packet& packet);

// The period of a MOT_SYSTEM_REPORT_REQ or DIO_REPORTS_REQ (µs) and axis mask.
struct ReportRequest {
  std::uint32_t period = 0;
  std::uint32_t axis_mask = 0;
};
[[nodiscard]] std::optional<ReportRequest> read_report_request(const Packet& packet);

// --- robot -> host

struct MotionReport {
  std::uint32_t timestamp = 0;
  std::uint8_t axis = kTranslationAxis;
  std::int32_t position = 0;  // arb
  std::int32_t velocity = 0;  // arb/s
  friend bool operator==(const MotionReport&, const MotionReport&) = default;
};
[[nodiscard]] Packet motion_report(const MotionReport& report, std::uint8_t id);
[[nodiscard]] std::optional<MotionReport> read_motion_report(const Packet& packet);

struct SystemStatus {
  std::uint32_t timestamp = 0;
  std::uint32_t voltage = 0;  // centivolts
  std::uint8_t brake = 0;
  friend bool operator==(const SystemStatus&, const SystemStatus&) = default;
};
[[nodiscard]] Packet system_status(const SystemStatus& status, std::uint8_t id);
[[nodiscard]] std::optional<SystemStatus> read_system_status(const Packet& packet);

struct SonarEcho {
  std::uint8_t id = 0;  // 16 x board + channel
  std::uint16_t range = 0;
  friend bool operator==(const SonarEcho&, const SonarEcho&) = default;
};
[[nodiscard]] Packet sonar_report(std::uint32_t timestamp, const std::vector<SonarEcho>& echoes, std::uint8_t id);
[[nodiscard]] std::optional<std::vector<SonarEcho>> read_sonar_report(const Packet& packet);

struct DioReport {
  std::uint32_t timestamp = 0;
  std::uint8_t address = 0;
  std::uint16_t value = 0;
  friend bool operator==(const DioReport&, const DioReport&) = default;
};
[[nodiscard]] Packet dio_report(const DioReport& report, std::uint8_t id);
[[nodiscard]] std::optional<DioReport> read_dio_report(const Packet& packet);

using IrBank = std::array<std::uint8_t, 8>;
[[nodiscard]] Packet ir_report(std::uint32_t timestamp, const std::vector<IrBank>& banks, std::uint8_t id);
[[nodiscard]] std::optional<std::vector<IrBank>> read_ir_report(const Packet& packet);

struct JoystickState {
  std::uint32_t timestamp = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::uint8_t buttons = 0;
  friend bool operator==(const JoystickState&, const JoystickState&) = default;
};
[[nodiscard]] Packet joystick_state(const JoystickState& state, std::uint8_t id);
[[nodiscard]] std::optional<JoystickState> read_joystick_state(const Packet& packet);

}  // namespace playerkit::hardware::rflex
