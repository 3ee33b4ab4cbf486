#pragma once
// The position a p2os_position device reports, from the robot's raw
// XPOS/YPOS/THPOS (p2os.md §2.3, §3.1), done the way 1.5 meant it:
//
//  * XPOS and YPOS are 12-bit counters: each SIP adds the shortest signed
//    step since the previous one (a wrap is a step, not a jump). Every step
//    the counters can express is accepted; 1.5 dropped steps over 100 mm
//    (quirk 5), which loses real motion above about 1 m/s.
//  * The reported pose is the robot's odometric pose seen through a
//    correction (SET_ODOM, RESET_ODOM, a reconnect): SET_ODOM sets x, y and
//    the heading exactly (1.5 used the upper 16 bits of theta, quirk 6).
//  * SETO makes the robot's counters jump to zero some time after it is
//    sent. The tracker keeps the reported pose continuous through that jump:
//    for a few SIPs after robot_reset_sent() it takes a SIP whose counters
//    are nearer zero than the previous reading for the robot's new origin.
//
// Units: millimetres and radians; the row gives the raw conversions. The
// counter arithmetic and the reported pose's correction are the shared
// interfaces::OdometryIntegrator; what is P2OS's own is here: 12-bit
// counters with a whole heading, sessions, and finding SETO's jump.

#include <cstdint>
#include <optional>

#include "algorithms/geometry/pose2.hpp"
#include "families/p2os/protocol/robot_params.hpp"
#include "interfaces/odometry_integrator.hpp"

namespace playerkit::drivers::p2os {

class OdometryTracker {
 public:
  // SIPs after a SETO in which the robot's jump to zero is looked for.
  static constexpr int kResetWindow = 4;

  explicit OdometryTracker(const hardware::p2os::RobotParams& params);

  // A new session (the row may differ). The next SIP is the robot's first:
  // on the first session the reported pose starts at x = y = 0 with the
  // robot's own heading; on later ones it continues where it stood.
  void start_session(const hardware::p2os::RobotParams& params);

  // One SIP's raw counters.
  void update(std::uint16_t x_position, std::uint16_t y_position, std::int16_t heading);

  // SETO was just written: the reported pose is (0, 0, 0) from now on,
  // whenever the robot's counters actually jump.
  void robot_reset_sent();
  // SET_ODOM: the reported pose becomes `pose` (mm, mm, rad) now.
  void set_pose(const geometry::Pose2& pose);

  // False until the first SIP of the first session.
  [[nodiscard]] bool ready() const { return have_reading_; }
  // x, y in mm, yaw in (-pi, pi].
  [[nodiscard]] geometry::Pose2 pose() const;
  // The robot's odometric pose (its own frame, counters unwrapped), mm and rad.
  [[nodiscard]] const geometry::Pose2& robot_pose() const { return odometry_.robot(); }

 private:
  struct Raw {
    std::uint16_t x = 0;
    std::uint16_t y = 0;
    std::int16_t heading = 0;
  };
  [[nodiscard]] double heading_radians(std::int16_t heading) const;
  // Whether `raw` looks like the first reading after the robot's reset.
  [[nodiscard]] bool looks_reset(const Raw& raw) const;

  const hardware::p2os::RobotParams* params_;
  interfaces::OdometryIntegrator odometry_;  // in mm: the robot's pose and the correction before it
  Raw last_;
  bool have_reading_ = false;
  bool session_started_ = false;  // false: the next reading opens a session
  bool first_session_ = true;
  int reset_window_ = 0;          // SIPs left in which to look for a SETO jump
  // Set between sessions, for the next session's first SIP: SET_ODOM's
  // pose, or (after SETO) the robot's counters taken as the pose.
  std::optional<geometry::Pose2> start_pose_;
  bool counters_are_pose_ = false;
};

// XPOS and YPOS are 12 bits wide.
inline constexpr int kPositionCounterBits = 12;

// The shortest signed difference between two 12-bit counter readings.
inline int wrapped_step(std::uint16_t now, std::uint16_t before) {
  return interfaces::wrapped_counter_step(now, before, kPositionCounterBits);
}

}  // namespace playerkit::drivers::p2os
