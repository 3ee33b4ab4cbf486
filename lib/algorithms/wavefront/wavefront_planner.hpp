#pragma once
// Global path planning on an occupancy grid: Player 1.5's wavefront driver
// (an NF1 navigation function grown from the goal, a penalty near walls, the
// successor chain reduced to line-of-sight waypoints), with the clearance
// kept as a guarantee: no point of the returned path, segments included,
// comes closer than robot_radius + safety_distance to an occupied cell, an
// unknown cell or the edge of the map. Steps cost their length (diagonals
// sqrt 2, not 1.5's 1), the wavefront stops once it reaches the start, and
// the waypoints are pulled taut round corners, every move checked.
//
//   wavefront::WavefrontPlanner planner(map, {.robot_radius = 0.2});  // once per map
//   auto plan = planner.plan(start, goal);                              // per goal
//   if (plan.found()) use(plan.waypoints);   // start first, goal last
//   else report(wavefront::describe_failure(plan, planner.parameters()));

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/wavefront/clearance_map.hpp"

namespace playerkit::wavefront {

struct PlannerParameters {
  double robot_radius = 0.15;     // m, 1.5's robot_radius
  double safety_distance = 0.15;  // m, 1.5's safety_dist (its default is robot_radius)
  // Beyond the required clearance, cells closer than this band cost more:
  // 1.5's penalty zone, moved out to start where the guarantee ends.
  double penalty_distance = 0.15;  // m
  // 1.5's dist_penalty: a step into a cell `m` metres short of the band's
  // outer edge costs (1 + distance_penalty * m / cell size) steps.
  double distance_penalty = 1.0;

  double required_clearance() const { return robot_radius + safety_distance; }
};

// Throws std::invalid_argument naming the parameter: robot_radius must be
// > 0, the others >= 0, all finite.
void validate(const PlannerParameters& parameters);

// Why a start or goal cannot be used.
enum class EndpointState {
  ok,
  outside_map,
  occupied,   // in an occupied cell
  unknown,    // in an unknown cell
  too_close,  // in a free cell, but nearer an obstacle than the required clearance
  cornered,   // clear itself, but no cell centre around it can be reached with the clearance
};

enum class PlanStatus { found, start_invalid, goal_invalid, unreachable };

struct PlanResult {
  PlanStatus status = PlanStatus::unreachable;
  EndpointState start = EndpointState::ok;
  EndpointState goal = EndpointState::ok;
  double start_clearance_m = 0.0;  // exact, at most the required clearance
  double goal_clearance_m = 0.0;
  // Found: the start, the waypoints, the goal (the start and goal exactly as given).
  std::vector<Eigen::Vector2d> waypoints;
  double length_m = 0.0;
  // Along every segment; capped at the planner's clearance().reach().
  double min_clearance_m = 0.0;
  std::size_t cells_settled = 0;  // by the wavefront (0 when the goal was in sight)
  // The wavefront's cost of the chain from the start to the goal, in cells,
  // penalties included: the navigation function at the start (0 in sight).
  double cost = 0.0;

  bool found() const { return status == PlanStatus::found; }
};

// One sentence for a plan that was not found ("start (1.00, 2.00) is in an
// occupied cell"); empty for a found plan.
std::string describe_failure(const PlanResult& result, const PlannerParameters& parameters);

class WavefrontPlanner {
 public:
  // The per-map work: clearances and step costs. Throws what validate and
  // ClearanceMap throw.
  explicit WavefrontPlanner(const grid::OccupancyGrid& grid, const PlannerParameters& parameters = {});

  // The per-goal work: the wavefront from the goal until it reaches the
  // start, the chain, the waypoints. Reuses its buffers (not thread-safe);
  // the answer depends only on the map, the parameters, start and goal.
  PlanResult plan(const Eigen::Vector2d& start, const Eigen::Vector2d& goal);

  // The wavefront is steered toward the start by a lower bound on the rest
  // of the way (A*): the same least cost, a fraction of the cells settled.
  // Off, it grows evenly from the goal (Dijkstra, as 1.5's does); for
  // comparison in tests and benchmarks.
  void use_goal_direction(bool on) { goal_directed_ = on; }

  const PlannerParameters& parameters() const { return parameters_; }
  const ClearanceMap& clearance() const { return clearance_; }

 private:
  struct Connection {
    std::size_t cell;  // padded index
    double cost;       // from the point to the cell centre, in cells
  };

  // What the wavefront found: the cost of the cheapest way from the start to
  // the goal (infinite: none) and the start's candidate cell it goes through.
  struct SearchOutcome {
    double cost = std::numeric_limits<double>::infinity();
    std::size_t start_cell = 0;  // padded index
    std::size_t cells_settled = 0;
  };

  EndpointState check_endpoint(const Eigen::Vector2d& point, double& clearance) const;
  // The wavefront from the goal's cells until no cheaper way to a start cell
  // can remain; leaves each reached cell's cost and successor in cells_.
  SearchOutcome search(const Eigen::Vector2d& start, const std::vector<Connection>& start_cells,
                       const std::vector<Connection>& goal_cells);
  // The start, the cell centres from first_cell along the successors, the goal.
  std::vector<Eigen::Vector2d> chain_from(std::size_t first_cell, const Eigen::Vector2d& start,
                                          const Eigen::Vector2d& goal) const;
  std::vector<Connection> connections(const Eigen::Vector2d& point) const;
  std::size_t padded_index(int col, int row) const;
  Eigen::Vector2d padded_centre(std::size_t index) const;
  std::vector<Eigen::Vector2d> waypoints_along(const std::vector<Eigen::Vector2d>& chain) const;
  void tighten(std::vector<Eigen::Vector2d>& waypoints) const;

  PlannerParameters parameters_;
  ClearanceMap clearance_;
  // Per cell, with a one-cell border of blocked cells so neighbours need no
  // bounds checks: whether it is free, whether diagonal steps keep the
  // clearance, its penalty level (wavefront_planner.cpp).
  struct Cell {
    float cost;  // per plan: the wavefront's cost to the goal, in steps
    // Low byte: free, diagonal steps, penalty level; high byte, per plan:
    // the plan it belongs to, the successor. Not a character type, so the
    // compiler need not assume stores to it change anything else.
    std::uint16_t bits;
  };
  std::size_t stride_ = 0;
  std::vector<Cell> cells_;
  std::array<float, 64> step_weight_{};  // the cost of a step into a cell, by penalty level

  // Dial's buckets, reused from plan to plan.
  struct Queued {
    std::uint32_t cell;
    float cost;  // when queued; the cell has been settled cheaper if it differs
  };
  unsigned generation_ = 0;
  bool goal_directed_ = true;
  std::vector<std::vector<Queued>> buckets_;
};

}  // namespace playerkit::wavefront
