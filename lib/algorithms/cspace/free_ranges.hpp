#pragma once
// A laser scan as configuration space for a round robot (lasercspace,
// manual 7.22, lasercspace.md §2): each beam is shortened to how far the
// robot's centre can travel along it before a disc of the robot's radius
// touches any return of the scan. Pure math: ranges in metres, angles in
// radians.

#include <span>
#include <vector>

namespace playerkit::cspace {

struct ScanGeometry {
  double first_bearing = 0;  // radians, of beam 0
  double bearing_step = 0;   // radians between consecutive beams
};

// For every beam n: the largest t in [0, r_n - radius] such that the disc of
// `radius` centred at t along beam n holds no return point p_i whose
// projection onto beam n lies between the origin and p_n (returns behind the
// sensor, or past the end of the beam, cannot shorten it). Only every
// `obstacle_stride`-th return is tested (1.5's undocumented `step`; 1 tests
// all). Negative results are 0. O(N^2) in the worst case; returns farther
// than the shortest candidate so far are skipped cheaply.
// Throws std::invalid_argument for a negative radius or a stride below 1.
std::vector<double> free_ranges(std::span<const double> ranges, ScanGeometry geometry, double radius,
                                int obstacle_stride = 1);

}  // namespace playerkit::cspace
