#pragma once
// What a viewer knows about a robot, built from the Player messages it
// receives; frame() turns it into shapes (shapes.hpp). No I/O: the caller
// reads messages and passes its own clock, so tests feed messages directly.
//
//   view::Scene scene;
//   scene.add_device(laser);                      // listed in the legend even while silent
//   scene.set_sensor_poses(sonar, poses);         // from the get-geom replies
//   scene.apply(message, now);                    // data of any device
//   auto frame = scene.frame(now);
//
// Frames are drawn in the world frame when the server gives one: the robot
// sits at its truth pose (a simulator), else at its best localize
// hypothesis, else at its odometry. Sensors hang off that pose. The odometry
// trail is odometry's own path, moved rigidly so that its end is where the
// robot is drawn: odometry drift shows as a trail bent away from the map.

#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <vector>

#include "client/typed/fiducial.hpp"
#include "client/typed/laser.hpp"
#include "client/typed/localize.hpp"
#include "client/typed/pose.hpp"
#include "protocol/device_address.hpp"
#include "protocol/message.hpp"
#include "view/rate_meter.hpp"
#include "view/shapes.hpp"

namespace playerkit::view {

struct SceneOptions {
  std::size_t trail_points = 2000;     // the newest odometry poses kept
  double trail_spacing = 0.02;         // m between kept poses: a robot standing still adds none
  double sonar_half_angle = 0.2618;    // rad (15 degrees): a Pioneer sonar's beam
  double ir_half_angle = 0.0436;       // rad (2.5 degrees)
  double ellipse_sigmas = 2.0;         // a hypothesis ellipse spans this many standard deviations
  double min_ellipse_axis = 0.05;      // m, so a confident estimate stays visible
  double fiducial_size = 0.2;          // m, the box a fiducial is drawn as
};

// A Pioneer 2-DX, until the position device's geometry says otherwise.
inline constexpr double kDefaultRobotLength = 0.44;
inline constexpr double kDefaultRobotWidth = 0.38;

class Scene {
 public:
  explicit Scene(SceneOptions options = {}) : options_(options) {}

  // A device to list in the legend, with its rate, before any data came.
  void add_device(protocol::DeviceAddress device);
  // Where a laser or a fiducial detector sits on the robot (its get-geom
  // reply); default the robot's centre.
  void set_mount_pose(protocol::DeviceAddress device, const client::Pose2D& pose);
  // Sonar or IR transducer poses on the robot; without them no cones are drawn.
  void set_sensor_poses(protocol::DeviceAddress device, std::vector<client::Pose2D> poses);
  void set_robot_size(double length, double width);

  // Takes a data message (others are ignored). `now` is the caller's clock
  // in seconds, for the rates. Data that does not decode is counted but not
  // drawn. Returns whether the message was data.
  bool apply(const protocol::Message& message, double now);

  // Where the robot is drawn, nullopt before any pose arrived.
  [[nodiscard]] std::optional<client::Pose2D> robot_pose() const;
  [[nodiscard]] Frame frame(double now) const;

 private:
  struct DeviceState {
    RateMeter rate;
    std::optional<client::LaserScan> scan;
    std::vector<double> ranges;  // sonar, IR
    std::optional<client::LocalizeEstimate> estimate;
    std::vector<client::Fiducial> fiducials;
  };

  void apply_position(protocol::DeviceAddress device, const protocol::Message& message);
  void add_sensor_shapes(protocol::DeviceAddress device, const DeviceState& state, const client::Pose2D& robot,
                         Frame& frame) const;
  void add_robot_shapes(const client::Pose2D& robot, Frame& frame) const;

  SceneOptions options_;
  std::map<protocol::DeviceAddress, DeviceState> devices_;
  std::map<protocol::DeviceAddress, client::Pose2D> mount_poses_;
  std::map<protocol::DeviceAddress, std::vector<client::Pose2D>> sensor_poses_;
  double robot_length_ = kDefaultRobotLength;
  double robot_width_ = kDefaultRobotWidth;
  // The first position device that sent data is the robot's odometry.
  std::optional<protocol::DeviceAddress> odometry_device_;
  std::optional<client::Pose2D> odometry_;
  std::deque<client::Pose2D> trail_;
  std::optional<client::Pose2D> truth_;
};

// a then b: b given in a's frame, returned in a's parent frame.
client::Pose2D compose(const client::Pose2D& a, const client::Pose2D& b);
// The inverse transform of a.
client::Pose2D invert(const client::Pose2D& a);

}  // namespace playerkit::view
