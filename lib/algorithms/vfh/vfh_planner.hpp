#pragma once
// One VFH+ step after another (vfh.md §2.4): from a scan and the direction
// of the goal, the direction to steer, the speed and the turn rate. The
// histogram, mask, openings and candidate costs are Player 1.5's (its
// sheet's worked cases come out the same); what happens after is better:
//
//  * the speed ramps up by `acceleration` but falls off smoothly to 0 as the
//    free distance along the chosen direction shrinks (1.5 only ramped up);
//  * with no way forward it turns in place towards the side with more room
//    and keeps turning that way until a way opens (1.5 always spun left,
//    forever);
//  * the caller may ask for less speed near its goal (`speed_limit`);
//  * a goal within a metre with nothing in the robot's way to it is driven
//    at straight, though the histogram, which looks 1.5 m and more ahead,
//    blocks its direction (1.5 could not reach a goal in an alcove).

#include <limits>
#include <optional>
#include <vector>

#include "algorithms/vfh/vfh_histogram.hpp"
#include "algorithms/vfh/vfh_parameters.hpp"

namespace playerkit::vfh {

struct Steering {
  std::optional<double> direction;  // degrees (90 ahead); none: no way forward
  double speed = 0;                 // m/s
  double turn_rate = 0;             // rad/s, positive to the left
  bool blocked = false;             // no opening: turning in place to find one
  std::vector<double> candidates;   // degrees, in the order they were weighed
};

class VfhPlanner {
 public:
  // Throws std::invalid_argument for bad parameters.
  explicit VfhPlanner(const VfhParameters& parameters);

  // `desired` is the goal's direction in degrees (90 straight ahead); `dt`
  // the seconds since the last step (for the speed ramp); `speed_limit`
  // caps the speed (m/s), e.g. to arrive at a goal without overshooting;
  // `goal_distance` (m), when known, lets it drive straight at a near goal
  // that nothing stands in front of.
  Steering step(const Scan& scan, double desired, double dt, double speed_limit,
                double goal_distance = std::numeric_limits<double>::infinity());

  // Forgets the ramp, the hysteresis and the previous direction (a new goal).
  void reset();

  [[nodiscard]] const VfhParameters& parameters() const { return window_.parameters(); }
  [[nodiscard]] double speed() const { return speed_; }

 private:
  [[nodiscard]] std::vector<bool> free_sectors(const HistogramWindow::Reading& reading);
  [[nodiscard]] std::vector<double> candidates(const std::vector<bool>& free, double desired) const;
  [[nodiscard]] double turn_rate_towards(double direction) const;
  [[nodiscard]] bool in_plain_view(const RangeTable& ranges, double desired, double goal_distance) const;

  HistogramWindow window_;
  std::vector<bool> binary_;          // blocked sectors, with hysteresis
  double previous_direction_ = 90;    // the last direction picked
  double speed_ = 0;                  // m/s, the ramp
  int escape_turn_ = 0;               // +1 left, -1 right while blocked; 0 otherwise
};

}  // namespace playerkit::vfh
