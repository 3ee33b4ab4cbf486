#pragma once
// For the rflex driver tests: an emulated RFLEX robot on a pty and its seven
// devices built from config text in 1.5's form, on the driver harness
// (drivers/driver_harness_test_support.hpp).

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include "core/device.hpp"
#include "drivers/driver_harness_test_support.hpp"
#include "emulators/runner/fault_plan.hpp"
#include "families/rflex/emulator/rflex_emulator.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers::rflex_testing {

using namespace std::chrono_literals;
using drivers::testing::acked;
using drivers::testing::ask;
using drivers::testing::data_sequence;
using drivers::testing::data_when;
using drivers::testing::eventually;
using drivers::testing::latest;
using drivers::testing::more_data;
using drivers::testing::nacked;
using drivers::testing::next_data;
using drivers::testing::write_command;
using emulators::rflex::RflexEmulator;
using emulators::rflex::RflexEmulatorOptions;

// `count` numbers of each group, as a 1.5 tuple: [a b c ...].
inline std::string tuple_of(int count, const std::function<std::string(int)>& group) {
  std::string text = "[";
  for (int i = 0; i < count; ++i) text += " " + group(i);
  return text + " ]";
}

// A B21r in 1.5's form (its b21r_rflex_lms200.cfg, data/config/rflex-b21r.cfg):
// 24 sonars on three boards, 14 bump panels, three IR banks.
inline std::string b21r_config(const std::string& extra_position = "") {
  const auto sonar_pose = [](int i) {
    const double theta = 2.0 * std::acos(-1.0) * i / 24.0;
    std::ostringstream out;
    out << std::fixed << theta << " " << 260 * std::cos(theta) << " " << 260 * std::sin(theta);
    return out.str();
  };
  return "position:0 ( driver \"rflex_position\" rflex_serial_port \"$PORT\" mm_length 520 mm_width 520 "
         "odo_distance_conversion 103 odo_angle_conversion 35000 default_trans_acceleration 500 "
         "default_rot_acceleration 1.0 " + extra_position + " )\n"
         "sonar:0 ( driver \"rflex_sonar\" range_distance_conversion 1.476 max_num_sonars 64 num_sonars 24 "
         "sonar_age 1 num_sonar_banks 3 num_sonars_possible_per_bank 16 num_sonars_in_bank [8 8 8] "
         "sonar_echo_delay 30000 mmrad_sonar_poses " + tuple_of(24, sonar_pose) + " )\n"
         "ir:0 ( driver \"rflex_ir\" rflex_base_bank 0 rflex_bank_count 3 rflex_banks [8 8 8] ir_min_range 100 "
         "ir_max_range 900 rflex_ir_calib " + tuple_of(24, [](int) { return std::string("4 1"); }) +
         " poses " + tuple_of(24, [](int i) { return std::to_string(i * 10) + " 0 " + std::to_string(i * 15); }) +
         " )\n"
         "bumper:0 ( driver \"rflex_bumper\" bumper_count 14 rflex_bumper_address 64 bumper_def " +
         tuple_of(14, [](int i) { return std::to_string(i) + ".7 2 " + std::to_string(i * 25) + " 100 260"; }) +
         " )\n"
         "power:0 ( driver \"rflex_power\" rflex_power_offset 12 )\n"
         "aio:0 ( driver \"rflex_aio\" )\n"
         "dio:0 ( driver \"rflex_dio\" rflex_done 1 )\n";
}

inline emulators::FaultPlan faults(std::initializer_list<std::string_view> arguments) {
  emulators::FaultPlan plan;
  for (std::string_view argument : arguments) emulators::add_fault(plan, argument);
  return plan;
}

class EmulatedRflex : public drivers::testing::EmulatedLine<RflexEmulator> {
 public:
  explicit EmulatedRflex(RflexEmulatorOptions options = {}, emulators::FaultPlan plan = {})
      : EmulatedLine([options] { return std::make_unique<RflexEmulator>(options); }, {.faults = plan}) {}

  geometry::Pose2 true_pose() {
    return with([](RflexEmulator& e) { return e.drive().true_pose(); });
  }
  bool stopped() {
    return with([](RflexEmulator& e) { return e.translation_command() == 0 && e.rotation_command() == 0; });
  }
};

struct RflexDevices : drivers::testing::ConfiguredDevices {
  RflexDevices(const std::string& port, const std::string& text) {
    builtin.logger.set_level(core::LogLevel::kDebug);
    load(text, port);
  }
  core::Device& position() { return device(protocol::kPositionCode); }
  core::Device& sonar() { return device(protocol::kSonarCode); }
  core::Device& ir() { return device(protocol::kIrCode); }
  core::Device& bumper() { return device(protocol::kBumperCode); }
  core::Device& power() { return device(protocol::kPowerCode); }
  core::Device& aio() { return device(protocol::kAioCode); }
  core::Device& dio() { return device(protocol::kDioCode); }
  std::uint64_t counter(core::Device& any, std::string_view name) {
    return drivers::testing::counter(any.driver(), name);
  }
};

}  // namespace playerkit::drivers::rflex_testing
