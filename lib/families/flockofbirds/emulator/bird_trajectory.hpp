#pragma once
// Where the emulated bird is at each moment: a scripted 6-DOF trajectory of
// timestamped poses, or a built-in motion when none is given. Pure: the
// text of a trajectory file is parsed here, the file is read by the caller.
//
// A trajectory file, one pose a line (blank lines and # comments skipped):
//
//   # seconds  x_mm   y_mm   z_mm  azimuth elevation roll (degrees)
//   0.0        300    0      100   0       0         0
//   2.5        300    200    100   90      10        -5
//
// Times start anywhere and must increase. Between two poses positions are
// interpolated in a straight line and angles the short way round; before
// the first the first pose holds; after the last the script starts again
// (looping) or the last pose holds.

#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "families/flockofbirds/protocol/bird_record.hpp"

namespace playerkit::emulators {

struct TimedBirdPose {
  double seconds = 0;
  hardware::flockofbirds::BirdPose pose;
};

class BirdTrajectory {
 public:
  // The built-in motion: a slow loop of 20 s in front of the transmitter
  // (x 200..400 mm, y -150..150 mm, z 50..150 mm), azimuth swinging ±90 deg,
  // elevation ±30, roll ±45.
  BirdTrajectory() = default;
  // Throws std::invalid_argument naming the line for a bad line, fewer than
  // one pose or times that do not increase.
  static BirdTrajectory parse(std::string_view text, bool loop);

  [[nodiscard]] hardware::flockofbirds::BirdPose at(std::chrono::nanoseconds since_start) const;
  [[nodiscard]] bool scripted() const { return !poses_.empty(); }
  [[nodiscard]] std::size_t size() const { return poses_.size(); }
  [[nodiscard]] double duration_seconds() const;

 private:
  std::vector<TimedBirdPose> poses_;
  bool loop_ = true;
};

[[nodiscard]] hardware::flockofbirds::BirdPose built_in_motion(double seconds);

}  // namespace playerkit::emulators
