#include "algorithms/vfh/vfh_histogram.hpp"

#include "algorithms/vfh/angles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace playerkit::vfh {

namespace {

// 1.5 converted radians with 360/6.28, not 180/pi; its thresholds and the
// sheet's worked cases are in that measure, so the window keeps it.
constexpr double kLegacyDegreesPerRadian = 360.0 / 6.28;
// 1.5's magnitude: (3000 mm - distance)^4 / 1e8, whatever the window.
constexpr double kMagnitudeReachMm = 3000.0;

double cell_direction(double right, double ahead) {
  if (right == 0 && ahead == 0) return -1;
  if (right == 0) return ahead > 0 ? 90 : 270;
  if (ahead == 0) return right > 0 ? 0 : 180;
  const double slope = std::atan(std::abs(ahead) / std::abs(right)) * kLegacyDegreesPerRadian;
  if (right > 0) return ahead > 0 ? slope : 360 - slope;
  return ahead > 0 ? 180 - slope : 180 + slope;
}

// Does [low, high] (degrees, possibly crossing 0) touch [start, end]?
bool overlaps(double low, double high, double start, double end) {
  for (const double shift : {-360.0, 0.0, 360.0}) {
    if (low + shift <= end && high + shift >= start) return true;
  }
  return false;
}

}  // namespace

void validate(const VfhParameters& p) {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("vfh: " + what);
  };
  require(p.cell_size > 0, "cell_size must be above 0");
  require(p.window_diameter >= 3 && p.window_diameter <= 401, "window_diameter must be 3 to 401 cells");
  require(p.sector_angle >= 1 && p.sector_angle <= 90 && 360 % p.sector_angle == 0,
          "sector_angle must divide 360 (1 to 90 degrees)");
  require(p.robot_radius >= 0 && p.safety_distance >= 0, "robot_radius and safety_dist must be 0 or more");
  require(p.max_speed >= 0, "max_speed must be 0 or more");
  require(p.max_turn_rate > 0 && p.min_turn_rate >= 0 && p.min_turn_rate <= p.max_turn_rate,
          "turn rates must satisfy 0 <= min_turnrate <= max_turnrate, max_turnrate above 0");
  require(p.free_space_cutoff <= p.obstacle_cutoff, "free_space_cutoff must not exceed obs_cutoff");
  require(p.weight_desired_direction >= 0 && p.weight_current_direction >= 0, "weights must be 0 or more");
  require(p.stop_distance >= 0 && p.slow_down_distance > 0 && p.acceleration > 0,
          "stop_distance, slow_down_distance and acceleration must be positive");
}

double angle_between(double a, double b) {
  const double d = std::abs(wrap_degrees(a) - wrap_degrees(b));
  return std::min(d, 360.0 - d);
}

RangeTable::RangeTable(const Scan& scan) : metres_(kBins, -1.0) {
  for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
    const double bearing = (scan.first_bearing + static_cast<double>(k) * scan.bearing_step) * 180.0 / std::numbers::pi;
    const long bin = std::lround((bearing + 90.0) * 2.0);
    if (bin < 0 || bin >= kBins || !(scan.ranges[k] > 0)) continue;
    metres_[static_cast<std::size_t>(bin)] = scan.ranges[k];
  }
  double last = kNoReading;
  for (double& bin : metres_) {
    if (bin < 0) bin = last;
    else last = bin;
  }
}

double RangeTable::at(double direction) const {
  const long bin = std::clamp(std::lround(direction * 2.0), 0L, static_cast<long>(kBins - 1));
  return metres_[static_cast<std::size_t>(bin)];
}

double RangeTable::nearest_around(double direction, double half_width) const {
  const long from = std::clamp(std::lround((direction - half_width) * 2.0), 0L, static_cast<long>(kBins - 1));
  const long to = std::clamp(std::lround((direction + half_width) * 2.0), 0L, static_cast<long>(kBins - 1));
  double nearest = kNoReading;
  for (long bin = from; bin <= to; ++bin) nearest = std::min(nearest, metres_[static_cast<std::size_t>(bin)]);
  return nearest;
}

bool RangeTable::strip_clear(double direction, double length, double half_width) const {
  for (std::size_t bin = 0; bin < metres_.size(); ++bin) {
    const double range = metres_[bin];
    if (range >= kNoReading) continue;
    const double off_line = (static_cast<double>(bin) / 2.0 - direction) * std::numbers::pi / 180.0;
    const double along = range * std::cos(off_line);
    if (along > 0 && along < length && std::abs(range * std::sin(off_line)) < half_width) return false;
  }
  return true;
}

HistogramWindow::HistogramWindow(const VfhParameters& parameters)
    : parameters_(parameters), sectors_(360 / std::max(parameters.sector_angle, 1)) {
  validate(parameters_);
  const int width = parameters_.window_diameter;
  const int centre = width / 2;
  const double cell_mm = parameters_.cell_size * 1000.0;
  const double enlarge_mm = (parameters_.robot_radius + parameters_.safety_distance) * 1000.0;
  cells_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(width));
  for (int row = 0; row < width; ++row) {
    for (int column = 0; column < width; ++column) {
      Cell& cell = cells_[static_cast<std::size_t>(row * width + column)];
      cell.x = column - centre;
      cell.y = centre - row;  // rows grow backwards
      const double distance_mm = cell_mm * std::hypot(cell.x, cell.y);
      cell.distance = distance_mm / 1000.0;
      cell.direction = cell_direction(cell.x, cell.y);
      cell.magnitude = std::pow(kMagnitudeReachMm - distance_mm, 4) / 1e8;
      if (cell.direction < 0) continue;
      const double enlargement = std::atan(enlarge_mm / distance_mm) * kLegacyDegreesPerRadian;
      for (int k = 0; k < sectors_; ++k) {
        const double start = k * parameters_.sector_angle;
        if (overlaps(cell.direction - enlargement, cell.direction + enlargement, start,
                     start + parameters_.sector_angle)) {
          cell.sectors.push_back(k);
        }
      }
    }
  }
}

HistogramWindow::Reading HistogramWindow::read(const RangeTable& ranges) const {
  Reading reading;
  reading.histogram.assign(static_cast<std::size_t>(sectors_), 0.0);
  const double half_cell = parameters_.cell_size / 2.0;
  for (std::size_t index = 0; index < cells_.size(); ++index) {
    const Cell& cell = cells_[index];
    // Only the half in front of the robot is seen; the robot's own cell is free.
    if (cell.direction < 0 || cell.direction >= 180) continue;
    // At or beyond the return in its direction: an obstacle, or hidden behind one.
    if (cell.distance + half_cell <= ranges.at(cell.direction)) continue;
    reading.occupied.push_back(static_cast<int>(index));
    for (const int k : cell.sectors) reading.histogram[static_cast<std::size_t>(k)] += cell.magnitude;
  }
  return reading;
}

double HistogramWindow::distance_to(int cell, double x, double y) const {
  const Cell& c = cells_[static_cast<std::size_t>(cell)];
  return parameters_.cell_size * std::hypot(c.x - x, c.y - y);
}

}  // namespace playerkit::vfh
