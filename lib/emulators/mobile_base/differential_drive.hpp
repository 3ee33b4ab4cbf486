#pragma once
// A round differential-drive robot in an occupancy grid: velocity
// setpoints, exact arc integration, stalling against occupied cells, and
// odometry that sees each step through the configured error. The body of
// every emulated mobile base (a Pioneer, an RFLEX robot, a Khepera...); the
// family's emulator adds its protocol, units and sensors.

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/mobile_base/odometry_error.hpp"

#include <optional>
#include <random>

namespace playerkit::emulators::mobile_base {

struct WheelVelocities {
  double left = 0.0;   // m/s
  double right = 0.0;  // m/s
  friend bool operator==(const WheelVelocities&, const WheelVelocities&) = default;
};

struct DriveGeometry {
  double wheelbase = 0.0;          // m
  double footprint_radius = 0.0;   // m
  double max_speed = 0.0;          // m/s, |v| limit
  double max_turn_rate = 0.0;      // rad/s, |ω| limit
};

// What happened against obstacles since the last take_contact().
struct Contact {
  bool stalled = false;
  double bearing = 0.0;  // of the last obstacle pushed against, robot frame, rad
};

class DifferentialDrive {
 public:
  DifferentialDrive(DriveGeometry geometry, const OdometryError& error,
                    const grid::OccupancyGrid* map, const geometry::Pose2& start);

  // Setpoints, clamped to the limits.
  void command(double speed, double turn_rate);
  void command_wheels(WheelVelocities wheels);
  void stop() { command(0.0, 0.0); }
  double commanded_speed() const { return speed_; }
  double commanded_turn_rate() const { return turn_rate_; }
  bool commanded_to_move() const { return speed_ != 0.0 || turn_rate_ != 0.0; }

  // Lets `seconds` pass in steps of at most `max_step` seconds.
  void run(double seconds, double max_step);

  const geometry::Pose2& true_pose() const { return true_pose_; }
  void set_true_pose(const geometry::Pose2& pose) { true_pose_ = pose; }
  const geometry::Pose2& odometry() const { return odometry_; }
  // Controllers that take an odometry origin (set-odometry commands).
  void set_odometry(const geometry::Pose2& pose) { odometry_ = pose; }
  void reset_odometry() { odometry_ = {}; }

  // The wheels as they turned in the last step: no forward motion while
  // pushing against an obstacle.
  WheelVelocities wheels() const;
  Contact take_contact();

 private:
  void step(double dt);
  bool blocked(const geometry::Pose2& from, const geometry::Pose2& to, double* bearing) const;

  DriveGeometry geometry_;
  OdometryError error_;
  const grid::OccupancyGrid* map_;
  geometry::Pose2 true_pose_;
  geometry::Pose2 odometry_;
  double speed_ = 0.0;
  double turn_rate_ = 0.0;
  bool last_step_blocked_ = false;
  Contact contact_;
  std::mt19937_64 random_;
};

// The pose reached from `pose` after driving `distance` along an arc that
// turns by `rotation` (exact for constant wheel speeds).
geometry::Pose2 drive_arc(const geometry::Pose2& pose, double distance, double rotation);

}  // namespace playerkit::emulators::mobile_base
