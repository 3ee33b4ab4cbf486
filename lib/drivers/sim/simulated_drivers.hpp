#pragma once
// The simulated devices, one class per interface (sim_drivers.hpp makes them
// from a configuration). Units on the wire are Player 1.5's: mm, degrees,
// 0.01° for laser angles, decivolts (wire_units.hpp).

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "drivers/sim/simulated_device.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::drivers::sim {

// Where `model` sits on its robot (the top-level model it rides on).
[[nodiscard]] geometry::Pose2 pose_on_robot(const World& world, ModelId model);

// position: odometry (or gps) pose in mm and degrees, velocity, stall.
// Commands: velocity (type 0) and position goals (type 1). Requests:
// GET_GEOM (body offset and size), MOTOR_POWER, VELOCITY_MODE and
// POSITION_MODE acknowledged, RESET_ODOM, SET_ODOM.
class SimPositionDriver final : public SimulatedDevice {
 public:
  SimPositionDriver(std::shared_ptr<SimulationHost> host, ModelId model, HeadingRange heading);

 private:
  void apply_command(World& world, const core::Command& command) override;
  [[nodiscard]] double reading_time(const World& world) const override;
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) override;
  core::RequestResult answer(World& world, const core::Request& request) override;

  HeadingRange heading_;
};

// How a laser's scan is served: which of the world's samples, in which units.
struct LaserView {
  int first = 0;      // the world's sample served first
  int count = 0;      // samples served (at most 401)
  int stride = 1;     // every stride-th sample of the world's
  std::uint16_t range_res = 1;  // mm per range unit
  bool intensity = true;
  // Set by SET_CONFIG (hundredths of a degree); nullopt: the world's scan.
  std::optional<protocol::LaserConfig> configured;
};

// The served layout of a world scan of `samples` over `fov` (rad), up to
// `range_max` (m): every sample when they fit in Player 1.5's 401, else every
// k-th (the smallest k that fits).
[[nodiscard]] LaserView default_laser_view(int samples, double range_max);
// The range unit that keeps `range_max` within 16 bits: 1, 10 or 100 mm.
[[nodiscard]] std::uint16_t range_resolution_for(double range_max);

// laser: the scan in mm (range_res) and 0.01°, at most 401 samples. Requests:
// GET_GEOM, GET_CONFIG, SET_CONFIG (resolution 25, 50 or 100 with angles up to
// ±50°, ±90°, ±180°, as Stage 1.3: the scan is recomputed; NACK otherwise),
// POWER acknowledged.
class SimLaserDriver final : public SimulatedDevice {
 public:
  SimLaserDriver(std::shared_ptr<SimulationHost> host, ModelId model);

 private:
  [[nodiscard]] double reading_time(const World& world) const override;
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) override;
  core::RequestResult answer(World& world, const core::Request& request) override;
  void unsubscribed() override;
  [[nodiscard]] protocol::LaserConfig current_config(const World& world) const;
  core::RequestResult set_config(World& world, const core::Request& request);

  LaserView view_;
};

// sonar: one range per transducer in mm (at most 64). Requests: GET_GEOM
// (transducer poses on the robot), POWER acknowledged.
class SimSonarDriver final : public SimulatedDevice {
 public:
  using SimulatedDevice::SimulatedDevice;

 private:
  [[nodiscard]] double reading_time(const World& world) const override;
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) override;
  core::RequestResult answer(World& world, const core::Request& request) override;
};

// fiducial: up to 32 sightings, range mm, bearing and orientation degrees, id
// -1 when too far to identify. Requests: GET_GEOM, GET_FOV.
class SimFiducialDriver final : public SimulatedDevice {
 public:
  using SimulatedDevice::SimulatedDevice;

 private:
  [[nodiscard]] double reading_time(const World& world) const override;
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) override;
  core::RequestResult answer(World& world, const core::Request& request) override;
};

// blobfinder: blobs by channel (up to 32 channels of 10 blobs), range mm.
class SimBlobfinderDriver final : public SimulatedDevice {
 public:
  using SimulatedDevice::SimulatedDevice;

 private:
  [[nodiscard]] double reading_time(const World& world) const override;
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) override;
};

// ptz: pan, tilt, zoom (the field of view) in degrees. Commands: pan and
// zoom (tilt is fixed at 0, as in Stage 1.3). Requests: CONTROL_MODE position
// acknowledged.
class SimPtzDriver final : public SimulatedDevice {
 public:
  using SimulatedDevice::SimulatedDevice;

 private:
  void apply_command(World& world, const core::Command& command) override;
  [[nodiscard]] double reading_time(const World& world) const override;
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) override;
  core::RequestResult answer(World& world, const core::Request& request) override;
};

// gripper: paddle state and beams as the Pioneer gripper's bits. Commands:
// the Pioneer gripper command set's open (GRIPopen, GRIPdeploy) and close
// (GRIPclose, GRIPstore); the others are ignored.
class SimGripperDriver final : public SimulatedDevice {
 public:
  using SimulatedDevice::SimulatedDevice;

 private:
  void apply_command(World& world, const core::Command& command) override;
  [[nodiscard]] double reading_time(const World& world) const override;
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) override;
};

// power: the battery voltage in decivolts. Requests: MAIN_POWER answered
// with the reading.
class SimPowerDriver final : public SimulatedDevice {
 public:
  using SimulatedDevice::SimulatedDevice;

 private:
  [[nodiscard]] double reading_time(const World& world) const override;
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) override;
  core::RequestResult answer(World& world, const core::Request& request) override;
};

// truth: the true global pose of the model's robot in mm and degrees, every
// step. Requests: GET_POSE, SET_POSE and SET_POSE_ON_ROOT (teleport the
// robot; odometry does not see the jump), GET_FIDUCIAL_ID.
class SimTruthDriver final : public SimulatedDevice {
 public:
  SimTruthDriver(std::shared_ptr<SimulationHost> host, ModelId model, HeadingRange heading);

 private:
  [[nodiscard]] double reading_time(const World& world) const override;
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) override;
  core::RequestResult answer(World& world, const core::Request& request) override;

  HeadingRange heading_;
};

// simulation: the world's run control, for scripts. Command byte (Player
// 1.5's simulation command is one driver-defined byte): 0 run, 1 pause,
// 2 one step then paused, 3 write the picture (player-serve --picture),
// applied at the next server cycle. A request whose
// first byte is one of them does the same before its ACK (1.5's simulation
// interface had no requests: programs that must know the world stopped ask).
// Data byte, and the ACK's: 1 while paused (or stopped at the run limit),
// else 0, published at every step and every change.
class SimControlDriver final : public core::Driver {
 public:
  static constexpr std::uint8_t kRun = 0;
  static constexpr std::uint8_t kPause = 1;
  static constexpr std::uint8_t kStep = 2;
  static constexpr std::uint8_t kPicture = 3;  // NACKed as a request when none was asked for

  explicit SimControlDriver(std::shared_ptr<SimulationHost> host);

  void prepare() override { host_->start(); }
  void setup() override;
  void shutdown() override;
  void update() override;
  core::RequestResult handle_request(const core::Request& request) override;

 private:
  // False for a byte that is none of the four, or a picture not written.
  bool control(std::uint8_t what);
  [[nodiscard]] std::uint8_t state() const;

  std::shared_ptr<SimulationHost> host_;
  core::SharedConnection::Use use_;
  double published_time_ = -1.0;
  int published_state_ = -1;
};

}  // namespace playerkit::drivers::sim
