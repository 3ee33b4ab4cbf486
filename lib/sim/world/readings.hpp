#pragma once
// What simulated devices read, in SI units, stamped with simulation time.
// The drivers (lib/drivers/sim) turn these into Player 1.5 structs.

#include <cstdint>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "sim/world/model_spec.hpp"

namespace playerkit::sim {

struct PositionReading {
  geometry::Pose2 pose;      // odometry (or gps) pose, in the localization frame
  geometry::Pose2 velocity;  // x, y in the robot frame (m/s), yaw rate (rad/s)
  bool stalled = false;      // the last step's move hit something and was undone
  double time = 0.0;
};

struct LaserScan {
  double min_angle = 0.0;   // bearing of the first sample, rad
  double max_angle = 0.0;   // of the last
  double range_max = 0.0;
  std::vector<double> ranges;       // m; range_max where nothing was hit
  std::vector<std::uint8_t> intensities;  // 1 for a bright return, else 0
  double time = 0.0;
};

struct SonarScan {
  std::vector<double> ranges;  // m, one per transducer in spec order
  double time = 0.0;
};

struct FiducialSighting {
  int id = 0;            // 0 beyond range_max_id
  double range = 0.0;    // m, centre to centre
  double bearing = 0.0;  // rad, in the finder's frame
  double orientation = 0.0;  // the target's heading relative to the finder's
  ModelId model = kNoModel;
};

struct FiducialScan {
  std::vector<FiducialSighting> sightings;
  double time = 0.0;
};

struct Blob {
  int channel = 0;
  Rgb color{};
  int left = 0, right = 0, top = 0, bottom = 0;  // image pixels
  int x = 0, y = 0;                               // centroid
  int area = 0;
  double range = 0.0;  // m, mean of the run's rays
};

struct BlobScan {
  int image_width = 0;
  int image_height = 0;
  std::vector<Blob> blobs;  // ordered by channel, then left to right
  double time = 0.0;
};

struct PtzReading {
  double pan = 0.0;  // rad
  double tilt = 0.0;
  double fov = 0.0;  // the zoom, as a field of view
  double time = 0.0;
};

enum class GripperPaddles { open, closed, moving };

struct GripperReading {
  GripperPaddles paddles = GripperPaddles::open;
  bool inner_beam = false;  // something between the paddles
  bool outer_beam = false;  // something just ahead of them
  int carried = 0;          // models held (or consumed)
  double time = 0.0;
};

struct PowerReading {
  double joules = 0.0;
  double volts = 0.0;
  double time = 0.0;
};

}  // namespace playerkit::sim
