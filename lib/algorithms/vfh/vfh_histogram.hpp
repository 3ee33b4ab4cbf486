#pragma once
// The VFH window (vfh.md §2.2-2.4): a square grid of cells around the robot,
// precomputed once (each cell's distance, direction, magnitude when occupied
// and the sectors its enlarged obstacle covers), and what one laser scan
// makes of it: the range table, the occupied cells and the primary polar
// histogram. Directions are Player 1.5's: degrees, 90 straight ahead, 0 the
// robot's right, 180 its left.

#include <span>
#include <vector>

#include "algorithms/vfh/vfh_parameters.hpp"

namespace playerkit::vfh {

// A scan as VFH reads it: bearings from the robot's heading, radians;
// ranges in metres (0 or less: no reading).
struct Scan {
  double first_bearing = 0;
  double bearing_step = 0;
  std::span<const double> ranges;
};

// Free distance by direction, in half degrees from the robot's right (0) to
// its left (360): the last reading at or before each half degree; metres.
class RangeTable {
 public:
  static constexpr int kBins = 361;
  static constexpr double kNoReading = 1000.0;  // before the first reading: nothing seen

  explicit RangeTable(const Scan& scan);
  // Direction in degrees (0..180).
  [[nodiscard]] double at(double direction) const;
  // The nearest reading within `half_width` degrees of `direction`.
  [[nodiscard]] double nearest_around(double direction, double half_width) const;
  // Whether no reading lies in the strip `half_width` either side of the
  // line from the robot towards `direction` (degrees), up to `length` (m).
  [[nodiscard]] bool strip_clear(double direction, double length, double half_width) const;

 private:
  std::vector<double> metres_;
};

class HistogramWindow {
 public:
  // Throws std::invalid_argument for bad parameters (validate()).
  explicit HistogramWindow(const VfhParameters& parameters);

  [[nodiscard]] int sectors() const { return sectors_; }
  [[nodiscard]] const VfhParameters& parameters() const { return parameters_; }

  struct Reading {
    std::vector<double> histogram;   // per sector, the summed magnitudes
    std::vector<int> occupied;       // cell indices seen occupied
  };
  [[nodiscard]] Reading read(const RangeTable& ranges) const;

  // For the mask: cell geometry.
  [[nodiscard]] double direction(int cell) const { return cells_[cell].direction; }
  // Distance in metres from the cell's centre to a point in cell units
  // (x right, y forward, from the robot).
  [[nodiscard]] double distance_to(int cell, double x, double y) const;

 private:
  struct Cell {
    double x = 0;           // cells right of the robot
    double y = 0;           // cells ahead of the robot
    double distance = 0;    // m from the robot
    double direction = -1;  // degrees; -1 for the robot's own cell
    double magnitude = 0;   // when occupied
    std::vector<int> sectors;
  };

  VfhParameters parameters_;
  int sectors_ = 0;
  std::vector<Cell> cells_;
};

// Angular distance between two directions in degrees, 0..180.
double angle_between(double a, double b);

}  // namespace playerkit::vfh
