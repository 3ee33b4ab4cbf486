#pragma once
// Readings cut short by something the map does not have: people round the
// robot, an open door's leaf, a parked cart. Fox, Burgard and Thrun's
// "distance filter" (Markov localization in dynamic environments, JAIR 1999)
// leaves out every reading that is shorter than the map allows from where
// the robot believes it is. Such a beam carries no news of the pose, and
// scored by a laser model it does harm: from a wrong pose the same endpoint
// may land on a wall and outscore the truth, which is how a crowd round a
// robot turning in place used to pull the track away.
//
// Readings that run long, through a mapped wall, are the other side: no
// unmapped obstacle makes a beam longer, so many of them say the estimate
// itself is wrong (a kidnapped robot), and then nothing should be left out.

#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/square_caster.hpp"

#include <cstddef>
#include <vector>

namespace playerkit::amcl {

// How far a reading may fall short of the map, or run past a wall, before
// it counts as either (metres). The second is wider: a wall a little behind
// a reading is an estimate a little off, which is not yet doubt.
struct ReadingMargins {
  double short_of_map = 0.2;
  double through_wall = 0.5;
};

enum class ReadingFit {
  fits,          // ends near where the map says, or cannot be told
  short_of_map,  // the map is free from the sensor to range + short_of_map
  through_wall,  // an occupied cell lies more than through_wall before the end
};

struct BeamFits {
  std::size_t returned = 0;  // beams with a return
  std::size_t short_of_map = 0;
  std::size_t through_wall = 0;
};

// Classifies readings against one map. Rays skip free space in squares
// (grid::SquareCaster: a byte a cell, built once), so a long reading costs a
// few steps rather than one per cell. Keeps a reference to `map`, which
// must outlive it.
class ReadingClassifier {
 public:
  explicit ReadingClassifier(const grid::OccupancyGrid& map);

  // How a reading of `range` from `sensor` (world frame) along `angle`
  // (world frame) fits the map. Unknown cells and the map's edge are not
  // known to be free: a ray meeting them first fits.
  ReadingFit classify(const geometry::Pose2& sensor, double angle, double range,
                      const ReadingMargins& margins) const;

  // The prepared `beams` classified from `robot`: the cheap question, asked
  // first, so a clean scan costs max_beams casts and not one per reading.
  BeamFits classify_beams(const geometry::Pose2& robot, const PreparedBeams& beams,
                          const ReadingMargins& margins) const;

  // Which readings of `scan`, taken at `robot`, to leave out when preparing
  // beams: at most `most_checked` usable readings, evenly spread, are
  // checked, and every reading that is short of the map or was not checked
  // is marked (bounding the cost on scans of many readings). Reuses `out`'s
  // storage; returns how many checked readings are short.
  std::size_t mark_short_readings(const geometry::Pose2& robot, const LaserScan& scan,
                                  const ReadingMargins& margins, std::size_t most_checked,
                                  std::vector<unsigned char>& out) const;

 private:
  const grid::OccupancyGrid& map_;
  grid::SquareCaster caster_;  // stops at anything not free
};

}  // namespace playerkit::amcl
