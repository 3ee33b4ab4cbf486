#include "view/scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "client/typed/message_as.hpp"
#include "client/typed/position.hpp"
#include "client/typed/ranging.hpp"
#include "client/typed/truth.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::view {
namespace {

using client::Pose2D;

Point point_of(const Pose2D& pose) { return {pose.x, pose.y}; }

// The point at `range` along the sensor's own x axis, in the world.
Point along(const Pose2D& sensor, double bearing, double range) {
  return {sensor.x + range * std::cos(sensor.yaw + bearing), sensor.y + range * std::sin(sensor.yaw + bearing)};
}

// A cone from the sensor out to `range`, its arc in a few straight pieces.
Area cone(const Pose2D& sensor, double range, double half_angle, Colour fill) {
  constexpr int kArcPieces = 6;
  Area area{{point_of(sensor)}, fill};
  for (int i = 0; i <= kArcPieces; ++i) {
    const double bearing = -half_angle + 2.0 * half_angle * i / kArcPieces;
    area.points.push_back(along(sensor, bearing, range));
  }
  return area;
}

const client::LocalizeHypothesis* best_hypothesis(const client::LocalizeEstimate& estimate) {
  const client::LocalizeHypothesis* best = nullptr;
  for (const auto& hypothesis : estimate.hypotheses) {
    if (!best || hypothesis.weight > best->weight) best = &hypothesis;
  }
  return best;
}

// The x-y block of the covariance as an ellipse: its eigenvalues are the
// variances along the axes.
Ellipse ellipse_of(const client::LocalizeHypothesis& hypothesis, double sigmas, double min_axis) {
  const double a = hypothesis.covariance[0][0], b = hypothesis.covariance[0][1], c = hypothesis.covariance[1][1];
  const double mean = 0.5 * (a + c);
  const double spread = std::sqrt(std::max(0.0, 0.25 * (a - c) * (a - c) + b * b));
  const double major = std::sqrt(std::max(0.0, mean + spread));
  const double minor = std::sqrt(std::max(0.0, mean - spread));
  return Ellipse{point_of(hypothesis.mean), std::max(min_axis, sigmas * major), std::max(min_axis, sigmas * minor),
                 0.5 * std::atan2(2.0 * b, a - c), colours::kHypothesis};
}

}  // namespace

Pose2D compose(const Pose2D& a, const Pose2D& b) {
  const double c = std::cos(a.yaw), s = std::sin(a.yaw);
  return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, a.yaw + b.yaw};
}

Pose2D invert(const Pose2D& a) {
  const double c = std::cos(a.yaw), s = std::sin(a.yaw);
  return {-c * a.x - s * a.y, s * a.x - c * a.y, -a.yaw};
}

void Scene::add_device(protocol::DeviceAddress device) { devices_.try_emplace(device); }

void Scene::set_mount_pose(protocol::DeviceAddress device, const Pose2D& pose) { mount_poses_[device] = pose; }

void Scene::set_sensor_poses(protocol::DeviceAddress device, std::vector<Pose2D> poses) {
  sensor_poses_[device] = std::move(poses);
}

void Scene::set_robot_size(double length, double width) {
  // A driver that answers its geometry with zeros would hide the robot.
  if (length > 0 && width > 0) {
    robot_length_ = length;
    robot_width_ = width;
  }
}

bool Scene::apply(const protocol::Message& message, double now) {
  if (message.type() != protocol::MessageType::kData) return false;
  const auto device = message.device();
  auto& state = devices_[device];
  state.rate.record(now);
  // A replayed log starts with an empty data packet, and a driver may send
  // what does not decode: neither may stop the view.
  if (message.payload.empty()) return true;
  try {
    switch (device.interface) {
      case protocol::kLaserCode:
        state.scan = client::to_si(client::data_as<protocol::LaserData>(message));
        break;
      case protocol::kSonarCode:
        state.ranges = client::to_si(client::data_as<protocol::SonarData>(message)).ranges;
        break;
      case protocol::kIrCode:
        state.ranges = client::to_si(client::data_as<protocol::IrData>(message)).ranges;
        break;
      case protocol::kFiducialCode:
        state.fiducials = client::to_si(client::data_as<protocol::FiducialData>(message));
        break;
      case protocol::kLocalizeCode:
        state.estimate = client::to_si(client::data_as<protocol::LocalizeData>(message));
        break;
      case protocol::kTruthCode:
        truth_ = client::to_si(client::data_as<protocol::TruthData>(message));
        break;
      case protocol::kPositionCode:
        apply_position(device, message);
        break;
      default:
        break;
    }
  } catch (const std::exception&) {
    // Counted in the rate above; there is nothing to draw.
  }
  return true;
}

void Scene::apply_position(protocol::DeviceAddress device, const protocol::Message& message) {
  if (!odometry_device_) odometry_device_ = device;
  if (device != *odometry_device_) return;
  const auto pose = client::to_si(client::data_as<protocol::PositionData>(message)).pose;
  odometry_ = pose;
  if (!trail_.empty() && std::hypot(pose.x - trail_.back().x, pose.y - trail_.back().y) < options_.trail_spacing) {
    return;
  }
  trail_.push_back(pose);
  while (trail_.size() > options_.trail_points) trail_.pop_front();
}

std::optional<Pose2D> Scene::robot_pose() const {
  if (truth_) return truth_;
  for (const auto& [device, state] : devices_) {
    if (!state.estimate) continue;
    if (const auto* best = best_hypothesis(*state.estimate)) return best->mean;
  }
  return odometry_;
}

Frame Scene::frame(double now) const {
  Frame frame;
  const Pose2D robot = robot_pose().value_or(Pose2D{});
  frame.centre = point_of(robot);

  if (odometry_ && trail_.size() >= 2) {
    // Odometry's path moved so that its newest pose lies on the robot.
    const Pose2D shift = compose(robot, invert(*odometry_));
    Line line{{}, colours::kTrail};
    for (const auto& pose : trail_) line.points.push_back(point_of(compose(shift, pose)));
    line.points.push_back(frame.centre);
    frame.lines.push_back(std::move(line));
  }
  for (const auto& [device, state] : devices_) add_sensor_shapes(device, state, robot, frame);
  if (truth_) {
    frame.bodies.push_back({*truth_, robot_length_, robot_width_, colours::kTruth, false});
  }
  add_robot_shapes(robot, frame);

  for (const auto& [device, state] : devices_) {
    frame.legend.push_back({protocol::to_string(device) + " " + format_rate(state.rate.rate(now)), colours::kText});
  }
  return frame;
}

void Scene::add_sensor_shapes(protocol::DeviceAddress device, const DeviceState& state, const Pose2D& robot,
                              Frame& frame) const {
  if (state.scan) {
    const auto found = mount_poses_.find(device);
    const Pose2D sensor = compose(robot, found == mount_poses_.end() ? Pose2D{} : found->second);
    const auto& scan = *state.scan;
    Area fan{{point_of(sensor)}, colours::kLaserFan};
    Dots plain{{}, colours::kLaserPoint, 1};
    Dots bright{{}, colours::kLaserBright, 2};
    for (std::size_t i = 0; i < scan.ranges.size() && i < scan.bearings.size(); ++i) {
      const Point hit = along(sensor, scan.bearings[i], scan.ranges[i]);
      fan.points.push_back(hit);
      const bool lit = i < scan.intensities.size() && scan.intensities[i] > 0;
      (lit ? bright : plain).points.push_back(hit);
    }
    frame.areas.push_back(std::move(fan));
    frame.dots.push_back(std::move(plain));
    if (!bright.points.empty()) frame.dots.push_back(std::move(bright));
  }
  if (!state.ranges.empty()) {
    const auto poses = sensor_poses_.find(device);
    if (poses != sensor_poses_.end()) {
      const bool sonar = device.interface == protocol::kSonarCode;
      const double half_angle = sonar ? options_.sonar_half_angle : options_.ir_half_angle;
      const Colour fill = sonar ? colours::kSonarCone : colours::kIrCone;
      for (std::size_t i = 0; i < state.ranges.size() && i < poses->second.size(); ++i) {
        frame.areas.push_back(cone(compose(robot, poses->second[i]), state.ranges[i], half_angle, fill));
      }
    }
  }
  if (!state.fiducials.empty()) {
    const auto found = mount_poses_.find(device);
    const Pose2D detector = compose(robot, found == mount_poses_.end() ? Pose2D{} : found->second);
    for (const auto& fiducial : state.fiducials) {
      const Point at = along(detector, fiducial.bearing, fiducial.range);
      const Pose2D marker{at.x, at.y, detector.yaw + fiducial.bearing + fiducial.orientation};
      frame.bodies.push_back(
          {marker, options_.fiducial_size, options_.fiducial_size, colours::kFiducial, false});
      frame.labels.push_back({at, fiducial.id < 0 ? std::string("?") : std::to_string(fiducial.id), colours::kFiducial});
    }
  }
  if (state.estimate) {
    for (const auto& hypothesis : state.estimate->hypotheses) {
      frame.ellipses.push_back(ellipse_of(hypothesis, options_.ellipse_sigmas, options_.min_ellipse_axis));
    }
  }
}

void Scene::add_robot_shapes(const Pose2D& robot, Frame& frame) const {
  frame.bodies.push_back({robot, robot_length_, robot_width_, colours::kRobot, true});
}

}  // namespace playerkit::view
