#pragma once
// An emulated RFLEX motion/sensor controller on a robot, written from
// rflex.md §6 ("what a faithful emulator must do"), so that Player 1.5's
// rflex drivers work against it unmodified:
//
//  * packets are cut by their length byte, the XOR checked; unknown or
//    broken ones are ignored;
//  * two axis counters (distance, bearing) in the model's arbitrary units,
//    driven by MOT_AXIS_SET_DIR (magnitude x direction) and integrated over
//    the robot's odometry (with its error) as it moves through the map;
//    SET_DEFAULTS zeroes the velocities, BRAKE_SET holds the robot until
//    BRAKE_RELEASE;
//  * after MOT_SYSTEM_REPORT_REQ a burst every period: one 34-byte report
//    per axis of the mask, then the sonar report (SONAR_RUN mode 2) and the
//    IR report (IR_RUN on), all at once, then silence until the next
//    period (1.5's reader needs gaps of 10 ms);
//  * SYS_STATUS and JSTK_GET_STATE answered at once;
//  * after DIO_REPORTS_REQ a DIO report per bump panel whenever one
//    changes (a panel is pressed while the robot pushes against the map in
//    its direction), and each panel's state once when reports start;
//  * a failsafe: no velocity command for `failsafe` seconds stops the robot
//    (1.5's driver repeats its command every loop for this reason).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/device_emulator.hpp"
#include "emulators/mobile_base/differential_drive.hpp"
#include "emulators/mobile_base/range_ring.hpp"
#include "families/rflex/emulator/rflex_models.hpp"
#include "families/rflex/protocol/rflex_messages.hpp"

namespace playerkit::emulators::rflex {

struct RflexEmulatorOptions {
  RflexModel model = *find_rflex_model("b21r");
  geometry::Pose2 initial_pose;
  mobile_base::OdometryError odometry_error;
  const grid::OccupancyGrid* map = nullptr;
  bool brake_at_start = false;
  double sonar_max_range = 5.0;  // m
  double ir_max_range = 1.0;     // m
  // No velocity command for this long stops the robot; 0: never.
  double failsafe = 1.0;  // s
};

class RflexEmulator final : public DeviceEmulator {
 public:
  explicit RflexEmulator(RflexEmulatorOptions options = {});

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override { return drive_.true_pose(); }
  [[nodiscard]] std::string describe() const override;

  // For tests.
  [[nodiscard]] const mobile_base::DifferentialDrive& drive() const { return drive_; }
  mobile_base::DifferentialDrive& drive() { return drive_; }
  [[nodiscard]] std::int32_t distance_counter() const;
  [[nodiscard]] std::int32_t bearing_counter() const;
  // Signed commanded velocities, arb/s.
  [[nodiscard]] std::int64_t translation_command() const { return velocity_[0]; }
  [[nodiscard]] std::int64_t rotation_command() const { return velocity_[1]; }
  [[nodiscard]] bool braked() const { return braked_; }
  [[nodiscard]] bool sonar_running() const { return sonar_on_; }
  [[nodiscard]] bool ir_running() const { return ir_on_; }
  [[nodiscard]] bool reporting_motion() const { return motion_period_ > Duration::zero() && axis_mask_ != 0; }
  [[nodiscard]] std::uint64_t commands() const { return commands_; }
  [[nodiscard]] std::uint64_t velocity_commands() const { return velocity_commands_; }
  [[nodiscard]] const RflexEmulatorOptions& options() const { return options_; }
  // A bump panel pressed by hand (tests), or released.
  void press_bumper(int panel, std::uint16_t corners);
  // The robot's joystick as JSTK_GET_STATE reports it (tests).
  void hold_joystick(const hardware::rflex::JoystickState& state) { joystick_ = state; }

 private:
  void execute(const hardware::rflex::Packet& packet);
  void move_to(Duration now);
  void report_burst();
  void update_bumpers();
  void send(const hardware::rflex::Packet& packet);
  [[nodiscard]] std::uint32_t timestamp() const;

  RflexEmulatorOptions options_;
  mobile_base::DifferentialDrive drive_;
  std::vector<std::uint8_t> sonar_ids_;  // before the ring: its constructor fills them
  mobile_base::RangeRing sonar_ring_;
  mobile_base::RangeRing ir_ring_;

  std::vector<std::uint8_t> input_;
  std::vector<Telegram> output_;
  Duration now_{0};
  std::uint8_t next_id_ = 0;
  std::uint64_t commands_ = 0;
  std::uint64_t velocity_commands_ = 0;

  std::int64_t velocity_[2] = {0, 0};  // arb/s, signed
  double distance_units_ = 0.0;        // the counters, unrounded
  double bearing_units_ = 0.0;
  bool braked_;
  Duration last_velocity_command_{0};

  Duration motion_period_{0};
  std::uint32_t axis_mask_ = 0;
  Duration next_report_{Duration::max()};
  bool dio_on_ = false;
  std::vector<std::uint16_t> bumpers_;
  std::vector<std::uint16_t> bumpers_reported_;
  std::vector<std::optional<std::uint16_t>> pressed_by_hand_;
  bool sonar_on_ = false;
  bool ir_on_ = false;
  hardware::rflex::JoystickState joystick_;  // nobody holds the button
};

}  // namespace playerkit::emulators::rflex
