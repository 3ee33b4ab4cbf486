#include "families/flockofbirds/emulator/bird_trajectory.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace playerkit::emulators {

namespace fob = hardware::flockofbirds;

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

std::string_view next_field(std::string_view& line) {
  const auto start = line.find_first_not_of(" \t\r");
  if (start == std::string_view::npos) {
    line = {};
    return {};
  }
  line.remove_prefix(start);
  const auto end = line.find_first_of(" \t\r");
  const std::string_view field = line.substr(0, end);
  line.remove_prefix(end == std::string_view::npos ? line.size() : end);
  return field;
}

[[noreturn]] void refuse(std::size_t line_number, const std::string& why) {
  throw std::invalid_argument("trajectory line " + std::to_string(line_number) + ": " + why);
}

double lerp(double a, double b, double t) { return a + (b - a) * t; }

// From a to b the short way round, in -180..180.
double lerp_angle(double a, double b, double t) {
  const double step = std::remainder(b - a, 360.0);
  return std::remainder(a + step * t, 360.0);
}

fob::BirdPose between(const fob::BirdPose& a, const fob::BirdPose& b, double t) {
  return {.x_mm = lerp(a.x_mm, b.x_mm, t),
          .y_mm = lerp(a.y_mm, b.y_mm, t),
          .z_mm = lerp(a.z_mm, b.z_mm, t),
          .azimuth_deg = lerp_angle(a.azimuth_deg, b.azimuth_deg, t),
          .elevation_deg = lerp_angle(a.elevation_deg, b.elevation_deg, t),
          .roll_deg = lerp_angle(a.roll_deg, b.roll_deg, t)};
}

}  // namespace

fob::BirdPose built_in_motion(double seconds) {
  const double turn = kTwoPi * seconds / 20.0;
  return {.x_mm = 300 + 100 * std::sin(turn),
          .y_mm = 150 * std::cos(turn),
          .z_mm = 100 + 50 * std::sin(2 * turn),
          .azimuth_deg = 90 * std::sin(turn),
          .elevation_deg = 30 * std::sin(kTwoPi * seconds / 7.0),
          .roll_deg = 45 * std::sin(kTwoPi * seconds / 13.0)};
}

BirdTrajectory BirdTrajectory::parse(std::string_view text, bool loop) {
  BirdTrajectory trajectory;
  trajectory.loop_ = loop;
  std::size_t line_number = 0;
  while (!text.empty()) {
    const auto end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    std::array<double, 7> values{};
    std::size_t count = 0;
    for (std::string_view field = next_field(line); !field.empty(); field = next_field(line)) {
      if (count == values.size()) refuse(line_number, "more than 7 numbers (t x y z azimuth elevation roll)");
      const auto [at, error] = std::from_chars(field.data(), field.data() + field.size(), values[count]);
      if (error != std::errc() || at != field.data() + field.size() || !std::isfinite(values[count])) {
        refuse(line_number, "'" + std::string(field.substr(0, 32)) + "' is not a number");
      }
      ++count;
    }
    if (count == 0) continue;
    if (count != values.size()) refuse(line_number, "expected 7 numbers (t x y z azimuth elevation roll)");
    if (!trajectory.poses_.empty() && values[0] <= trajectory.poses_.back().seconds) {
      refuse(line_number, "the time must increase");
    }
    trajectory.poses_.push_back({values[0],
                                 {.x_mm = values[1],
                                  .y_mm = values[2],
                                  .z_mm = values[3],
                                  .azimuth_deg = values[4],
                                  .elevation_deg = values[5],
                                  .roll_deg = values[6]}});
  }
  if (trajectory.poses_.empty()) throw std::invalid_argument("trajectory: no pose in it");
  return trajectory;
}

double BirdTrajectory::duration_seconds() const {
  return poses_.empty() ? 20.0 : poses_.back().seconds - poses_.front().seconds;
}

fob::BirdPose BirdTrajectory::at(std::chrono::nanoseconds since_start) const {
  const double seconds = std::chrono::duration<double>(since_start).count();
  if (poses_.empty()) return built_in_motion(seconds);
  const double first = poses_.front().seconds;
  double t = first + seconds;
  const double duration = duration_seconds();
  if (loop_ && duration > 0 && t > poses_.back().seconds) t = first + std::fmod(t - first, duration);
  if (t <= first) return poses_.front().pose;
  if (t >= poses_.back().seconds) return poses_.back().pose;
  const auto later = std::lower_bound(poses_.begin(), poses_.end(), t,
                                     [](const TimedBirdPose& pose, double time) { return pose.seconds < time; });
  const TimedBirdPose& a = *(later - 1);
  const TimedBirdPose& b = *later;
  return between(a.pose, b.pose, (t - a.seconds) / (b.seconds - a.seconds));
}

}  // namespace playerkit::emulators
