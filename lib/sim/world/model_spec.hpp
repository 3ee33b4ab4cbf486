#pragma once
// What a simulated model is made of: the description a world file (or a
// test) gives before the world runs. One ModelSpec per model; a robot is a
// `position` model with its sensors as children, riding on it.
//
// Units are SI inside (metres, radians, seconds); world files' degrees and
// milliseconds are converted by lib/sim/worldfile.

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "algorithms/geometry/pose2.hpp"

namespace playerkit::sim {

using ModelId = std::int32_t;
inline constexpr ModelId kNoModel = -1;

struct Rgb {
  std::uint8_t r = 255;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  // 0xRRGGBB, as Player's blobfinder reports a blob's colour.
  [[nodiscard]] std::uint32_t packed() const { return (std::uint32_t{r} << 16) | (std::uint32_t{g} << 8) | b; }
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

enum class Shape { rectangle, circle };

// The part of a model that collides and that rays hit: a rectangle of
// size.x by size.y, or a circle of diameter size.x, centred on the model's
// pose composed with `offset` (Stage's `origin`, 1.3's `offset`).
struct Body {
  Shape shape = Shape::rectangle;
  Eigen::Vector2d size{0.4, 0.4};
  geometry::Pose2 offset{};
  bool present = true;  // false: no body at all (sensors, Stage's `noblocks 1`)
};

// How other models' sensors and bodies treat this one.
struct Returns {
  bool obstacle = true;         // collides with robots
  double ranger = 1.0;          // < 0: rangers see through it; else the intensity they report
  bool laser_bright = false;    // Stage 1.3 `laser_return "bright"`: intensity 1 on a laser
  int fiducial_id = 0;          // 0: not a fiducial
  int fiducial_key = 0;
  bool gripper = false;         // grippers can pick it up
  bool blob = true;             // blobfinders see its colour
};

enum class Drive { differential, omnidirectional, car };
enum class Localization { gps, odometry };

struct PositionSpec {
  Drive drive = Drive::differential;
  // Commanded velocities (x, y, yaw: m/s, m/s, rad/s) are clamped to these.
  Eigen::Vector3d min_velocity{-1.0, -1.0, -std::numbers::pi / 2};
  Eigen::Vector3d max_velocity{1.0, 1.0, std::numbers::pi / 2};
  // Largest change of velocity per second (m/s², m/s², rad/s²); infinite:
  // the commanded velocity is reached at once, as in Stage.
  Eigen::Vector3d max_acceleration = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  double wheelbase = 1.0;  // m, car drive only
  Localization localization = Localization::odometry;
  // The frame odometry (and gps) poses are reported in; nullopt: the
  // model's start pose, so odometry starts at (0, 0, 0).
  std::optional<geometry::Pose2> localization_origin;
  // Stage's odom_error: relative error of the integrated x, y and yaw
  // motion. nullopt: drawn once from the world's seed within Stage's
  // defaults (±0.015, ±0.015, ±0.025).
  std::optional<Eigen::Vector3d> odom_error = Eigen::Vector3d::Zero();
  Eigen::Vector3d initial_velocity = Eigen::Vector3d::Zero();
  double mass_kg = 0.0;  // power drain only
};

// A scanning laser (Stage 1.3 `laser`, Stage 3 `laser`, a Stage 4 ranger
// with one many-sample sensor).
struct LaserSpec {
  geometry::Pose2 pose{};  // the scan origin in the model's frame
  double range_min = 0.0;
  double range_max = 8.0;
  double fov = std::numbers::pi;
  int samples = 361;           // first and last on the edges of the fov
  double noise_sd = 0.0;       // m, Gaussian on ranges below range_max
  double noise_proportional = 0.0;  // ± this fraction of the range, uniform
  double angle_jitter = 0.0;   // fraction of the sample spacing, uniform
  double interval = 0.1;       // s between scans
};

// A ring of one-ray transducers (Stage 1.3 `sonar`, Stage 3 `ranger`, a
// Stage 4 ranger with several one-sample sensors).
struct SonarSpec {
  std::vector<geometry::Pose2> transducers;  // in the model's frame
  double range_min = 0.0;  // shorter readings are raised to it
  double range_max = 5.0;
  double noise_sd = 0.0;
  double interval = 0.1;
};

struct FiducialSpec {
  double range_min = 0.0;
  double range_max = 8.0;     // detection, centre to centre
  double range_max_id = 5.0;  // beyond it the id reads 0
  double fov = std::numbers::pi;
  int key = 0;
  double interval = 0.2;
};

struct BlobfinderSpec {
  std::vector<Rgb> channels;  // empty: every colour is a channel of its own
  int image_width = 80;
  int image_height = 60;
  double range = 12.0;
  double fov = std::numbers::pi / 3;  // unless a ptz parent sets it
  double interval = 0.1;
};

// The pan/zoom head a blobfinder may sit on (Stage 1.3 `ptz`).
struct PtzSpec {
  double max_fov = std::numbers::pi / 3;  // "normal" lens 60°, "wide" 120°
  double min_fov = std::numbers::pi / 36;  // max_fov / 12
  double pan_limit = 100.0 * std::numbers::pi / 180.0;
  double interval = 0.1;
};

struct GripperSpec {
  bool consume = false;  // picked-up models vanish (capacity unbounded)
  int capacity = 1;
  double reach = 0.1;  // m ahead of the body's front edge that the beams see
};

struct PowerSpec {
  double capacity_joules = 100'000.0;
  double idle_watts = 1.0;
  double watts_per_mps = 20.0;  // added per m/s of the robot's speed
  double full_volts = 13.0;
  double empty_volts = 10.0;
  double interval = 1.0;
};

struct TruthSpec {};
struct ObjectSpec {};  // walls, boxes, pucks, beacons: a body and returns only

using ModelParams = std::variant<ObjectSpec, PositionSpec, LaserSpec, SonarSpec, FiducialSpec, BlobfinderSpec,
                                 PtzSpec, GripperSpec, PowerSpec, TruthSpec>;

struct ModelSpec {
  std::string name;  // unique in a world; generated when empty ("position:0")
  std::string type;  // the world file's word for it ("position", "lbd", "pioneer2dx"'s base "position")
  ModelId parent = kNoModel;
  geometry::Pose2 pose{};  // in the parent's frame; the world's at top level
  Body body{};
  Rgb color{};
  Returns returns{};
  // Player addressing of Stage 1.3 worlds: the robot's port (0: the
  // server's default port) and an explicit device index (nullopt: next free).
  std::uint16_t port = 0;
  std::optional<int> index;
  ModelParams params{};
};

}  // namespace playerkit::sim
