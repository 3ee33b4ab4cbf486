#include "algorithms/wavefront/wavefront_planner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <limits>
#include <stdexcept>

namespace playerkit::wavefront {
namespace {

constexpr double kSqrt2 = 1.4142135623730951;
// Around a start or goal, cell centres within this many cells are tried as
// the first or last cell of the chain.
constexpr int kConnectionRadius = 2;

// Cell::bits, low byte (per map): 0 blocked; else free, whether diagonal
// steps into and out of it keep the clearance, a penalty level 0..63.
constexpr std::uint16_t kFreeClass = 0x80;
constexpr std::uint16_t kDiagonalOk = 0x40;
constexpr std::size_t kLevelMask = 0x3F;
constexpr std::uint16_t kKindMask = 0xFF;
// High byte (per plan): the plan's generation (the cost is this plan's only
// when it matches), whether the cell has a successor, toward which
// neighbour (an index into kNeighbours).
constexpr int kDirectionShift = 8;
constexpr std::uint16_t kHasSuccessor = 0x0800;
constexpr int kGenerationShift = 12;
constexpr unsigned kGenerations = 15;
constexpr std::size_t kPrefetchAhead = 8;

struct Neighbour {
  int dcol, drow;
  bool diagonal;
};
// Opposite directions are 7 - k apart.
constexpr std::array<Neighbour, 8> kNeighbours{{
    {-1, -1, true}, {0, -1, false}, {1, -1, true}, {-1, 0, false},
    {1, 0, false},  {-1, 1, true},  {0, 1, false}, {1, 1, true},
}};

// The shortest 8-connected way between two cells, in cells.
double octile(int dcol, int drow) {
  const int a = std::abs(dcol), b = std::abs(drow);
  return std::max(a, b) + (kSqrt2 - 1.0) * std::min(a, b);
}

// A lower bound on the cost from a cell to the start, for the search from
// the goal: every step costs at least its length, so the way to a candidate
// start cell c costs at least octile(cell, c), and the way in from c at least
// octile(cell, start's cell) - slack, slack being the most any candidate
// saves. It changes by at most a step's length across a step (consistent).
// Shrunk a little, so float rounding never lifts it above the true cost.
// Off, it is 0 everywhere.
class RemainingBound {
 public:
  RemainingBound(bool on, int col, int row, double slack)
      : col_(col), row_(row), slack_(static_cast<float>(slack)), shrink_(on ? 0.9999f : 0.0f) {}
  float operator()(int col, int row) const {
    const auto a = static_cast<float>(std::abs(col - col_)), b = static_cast<float>(std::abs(row - row_));
    return std::max((std::max(a, b) + kDiagonalExtra * std::min(a, b) - slack_) * shrink_, 0.0f);
  }

 private:
  static constexpr float kDiagonalExtra = static_cast<float>(kSqrt2 - 1.0);
  int col_, row_;
  float slack_;
  float shrink_;
};

}  // namespace

void validate(const PlannerParameters& p) {
  const auto check = [](double value, bool positive, const char* name) {
    if (!std::isfinite(value) || value < 0.0 || (positive && value == 0.0)) {
      throw std::invalid_argument(std::string(name) + (positive ? " must be > 0" : " must be >= 0") +
                                  " and finite");
    }
  };
  check(p.robot_radius, true, "robot_radius");
  check(p.safety_distance, false, "safety_distance");
  check(p.penalty_distance, false, "penalty_distance");
  check(p.distance_penalty, false, "distance_penalty");
}

// The graph: cell centres whose clearance is at least the required one.
// A straight step between two such centres keeps it all along (against any
// one square the distance is monotonic along an axis-parallel step), a
// diagonal one may dip in the middle: the squared distance to a square is
// convex along the step with second derivative at most 4 cells^2, so it
// dips at most half a cell^2 below the smaller end. Diagonal steps are
// therefore allowed only between centres with 4 q >= 4 R^2 + 2.
WavefrontPlanner::WavefrontPlanner(const grid::OccupancyGrid& grid, const PlannerParameters& parameters)
    : parameters_(parameters) {
  validate(parameters_);
  const double resolution = grid.resolution();
  const double required = parameters_.required_clearance();
  const double comfortable = required + parameters_.penalty_distance;
  clearance_ = ClearanceMap(grid, std::max(comfortable, required + 2.0 * resolution));

  const int width = grid.width(), height = grid.height();
  stride_ = static_cast<std::size_t>(width) + 2;
  const std::size_t padded = stride_ * (static_cast<std::size_t>(height) + 2);
  if (padded >= std::numeric_limits<std::uint32_t>::max()) throw std::invalid_argument("WavefrontPlanner: grid too large");

  // Per stored clearance (whole quarter squares up to the cap): blocked,
  // or a penalty level and whether diagonal steps keep the clearance.
  const double required_cells = required / resolution;
  const double comfortable_cells = comfortable / resolution;
  // Rounding slack far below a nanometre; stored values are whole numbers.
  const double free_quarter = 4.0 * required_cells * required_cells - 1e-6;
  const double diagonal_quarter = free_quarter + 2.0;
  const double band_cells = comfortable_cells - required_cells;
  for (std::size_t level = 0; level <= kLevelMask; ++level) {
    const double short_of_comfort = level == 0 ? 0.0 : band_cells * static_cast<double>(level) / kLevelMask;
    step_weight_[level] = static_cast<float>(1.0 + parameters_.distance_penalty * short_of_comfort);
  }
  const auto cap = static_cast<std::size_t>(4.0 * clearance_.reach_cells() * clearance_.reach_cells());
  std::vector<std::uint8_t> class_of(cap + 1, 0);
  for (std::size_t quarter = 0; quarter <= cap; ++quarter) {
    const auto q = static_cast<double>(quarter);
    if (q < free_quarter) continue;
    // The penalty in 63 steps across the band, rounded up.
    const double short_of_comfort = std::max(comfortable_cells - 0.5 * std::sqrt(q), 0.0);
    const auto level = static_cast<std::uint8_t>(
        band_cells > 0.0 ? std::ceil(std::min(short_of_comfort / band_cells, 1.0) * kLevelMask) : 0.0);
    class_of[quarter] = static_cast<std::uint8_t>(kFreeClass | level | (q >= diagonal_quarter ? kDiagonalOk : 0));
  }

  cells_.assign(padded, Cell{0.0f, 0});
  for (int row = 0; row < height; ++row) {
    Cell* out = &cells_[padded_index(0, row)];
    for (int col = 0; col < width; ++col) {
      out[col].bits = class_of[static_cast<std::size_t>(clearance_.quarter_squared(col, row))];
    }
  }
  // Buckets one cost unit wide (plan()). A step raises the estimate of the
  // whole way by at most its cost plus its length, so live buckets span at
  // most that for the heaviest diagonal step. A power of two, so the bucket
  // of an estimate is a mask away.
  const auto needed = static_cast<std::size_t>(std::ceil(kSqrt2 * (step_weight_[kLevelMask] + 1.0))) + 2;
  std::size_t bucket_count = 1;
  while (bucket_count < needed) bucket_count *= 2;
  buckets_.resize(bucket_count);
}

std::size_t WavefrontPlanner::padded_index(int col, int row) const {
  return (static_cast<std::size_t>(row) + 1) * stride_ + static_cast<std::size_t>(col) + 1;
}

Eigen::Vector2d WavefrontPlanner::padded_centre(std::size_t index) const {
  const auto row = static_cast<int>(index / stride_) - 1;
  const auto col = static_cast<int>(index % stride_) - 1;
  return clearance_.cell_centre(col, row);
}

EndpointState WavefrontPlanner::check_endpoint(const Eigen::Vector2d& point, double& clearance) const {
  const double required = parameters_.required_clearance();
  clearance = 0.0;
  if (!point.allFinite()) return EndpointState::outside_map;
  const Eigen::Vector2i cell = clearance_.cell_of(point);
  if (!clearance_.contains(cell.x(), cell.y())) return EndpointState::outside_map;
  const grid::CellState state = clearance_.state(cell.x(), cell.y());
  if (state == grid::CellState::occupied) return EndpointState::occupied;
  if (state == grid::CellState::unknown) return EndpointState::unknown;
  clearance = clearance_.point_clearance(point, required);
  if (clearance < required - kClearanceTolerance) return EndpointState::too_close;
  return EndpointState::ok;
}

std::vector<WavefrontPlanner::Connection> WavefrontPlanner::connections(const Eigen::Vector2d& point) const {
  std::vector<Connection> found;
  const Eigen::Vector2i cell = clearance_.cell_of(point);
  const double required = parameters_.required_clearance();
  for (int row = cell.y() - kConnectionRadius; row <= cell.y() + kConnectionRadius; ++row) {
    for (int col = cell.x() - kConnectionRadius; col <= cell.x() + kConnectionRadius; ++col) {
      if (!clearance_.contains(col, row)) continue;
      const std::size_t i = padded_index(col, row);
      if (!(cells_[i].bits & kFreeClass)) continue;
      const Eigen::Vector2d centre = clearance_.cell_centre(col, row);
      if (!clearance_.segment_keeps(point, centre, required)) continue;
      found.push_back({i, (centre - point).norm() / clearance_.resolution()});
    }
  }
  return found;
}

PlanResult WavefrontPlanner::plan(const Eigen::Vector2d& start, const Eigen::Vector2d& goal) {
  PlanResult result;
  const double required = parameters_.required_clearance();
  result.start = check_endpoint(start, result.start_clearance_m);
  result.goal = check_endpoint(goal, result.goal_clearance_m);
  if (result.start != EndpointState::ok) {
    result.status = PlanStatus::start_invalid;
    return result;
  }
  if (result.goal != EndpointState::ok) {
    result.status = PlanStatus::goal_invalid;
    return result;
  }
  const auto finish = [&](std::vector<Eigen::Vector2d> waypoints) {
    result.status = PlanStatus::found;
    result.waypoints = std::move(waypoints);
    result.length_m = 0.0;
    for (std::size_t i = 1; i < result.waypoints.size(); ++i) {
      result.length_m += (result.waypoints[i] - result.waypoints[i - 1]).norm();
    }
    result.min_clearance_m = clearance_.polyline_clearance(result.waypoints, clearance_.reach());
    return result;
  };
  // In sight: nothing is shorter.
  if (clearance_.segment_keeps(start, goal, required)) return finish({start, goal});

  const std::vector<Connection> goal_cells = connections(goal);
  const std::vector<Connection> start_cells = connections(start);
  if (goal_cells.empty()) result.goal = EndpointState::cornered;
  if (start_cells.empty()) result.start = EndpointState::cornered;
  if (start_cells.empty() || goal_cells.empty()) {
    result.status = start_cells.empty() ? PlanStatus::start_invalid : PlanStatus::goal_invalid;
    return result;
  }

  const SearchOutcome outcome = search(start, start_cells, goal_cells);
  result.cells_settled = outcome.cells_settled;
  if (!std::isfinite(outcome.cost)) return result;  // unreachable
  result.cost = outcome.cost;
  return finish(waypoints_along(chain_from(outcome.start_cell, start, goal)));
}

WavefrontPlanner::SearchOutcome WavefrontPlanner::search(const Eigen::Vector2d& start,
                                                         const std::vector<Connection>& start_cells,
                                                         const std::vector<Connection>& goal_cells) {
  // A new generation makes every cost of earlier plans stale without
  // touching them; only every 15th plan clears the flags.
  if (++generation_ > kGenerations) {
    generation_ = 1;
    for (Cell& cell : cells_) cell.bits &= kKindMask;
  }
  // The start's candidate cells lie in a small box: most settled cells are
  // ruled out by one comparison.
  std::size_t start_box_first = std::numeric_limits<std::size_t>::max(), start_box_last = 0;
  for (const Connection& c : start_cells) {
    start_box_first = std::min(start_box_first, c.cell);
    start_box_last = std::max(start_box_last, c.cell);
  }
  const Eigen::Vector2i start_cell = clearance_.cell_of(start);
  const RemainingBound remaining(goal_directed_, start_cell.x() + 1, start_cell.y() + 1, [&] {
    // How much shorter than the octile distance to the start's own cell the
    // way in through a candidate cell can be.
    double slack = 0.0;
    for (const Connection& c : start_cells) {
      slack = std::max(slack, octile(static_cast<int>(c.cell % stride_) - (start_cell.x() + 1),
                                     static_cast<int>(c.cell / stride_) - (start_cell.y() + 1)) - c.cost);
    }
    return slack;
  }());

  // Locals, so that the loop below keeps them in registers.
  Cell* const cells = cells_.data();
  const auto generation = static_cast<std::uint16_t>(generation_);
  const auto stamp = static_cast<std::uint16_t>(generation << kGenerationShift);
  const std::size_t bucket_mask = buckets_.size() - 1;
  const auto stride = static_cast<std::uint32_t>(stride_);
  std::array<float, kLevelMask + 1> step_weight = step_weight_;
  std::size_t queued = 0;
  const auto goal_estimate = [&](const Connection& c) {
    return static_cast<float>(c.cost) +
           remaining(static_cast<int>(c.cell % stride), static_cast<int>(c.cell / stride));
  };
  // The first bucket: the least estimate (buckets are a ring).
  std::size_t level = std::numeric_limits<std::size_t>::max();
  for (const Connection& c : goal_cells) level = std::min(level, static_cast<std::size_t>(goal_estimate(c)));
  for (auto& bucket : buckets_) bucket.clear();
  // Bucketed by the estimate of the whole way (cost so far plus the bound on
  // the rest). Rounding may put an estimate a hair below the bucket being
  // worked on; it then joins that bucket.
  const auto push = [&](std::size_t cell, float cost, float estimate) {
    const std::size_t bucket = std::max(static_cast<std::size_t>(estimate), level) & bucket_mask;
    buckets_[bucket].push_back({static_cast<std::uint32_t>(cell), cost});
    ++queued;
  };
  const auto current = [&](const Cell& cell) { return (cell.bits >> kGenerationShift) == generation; };
  for (const Connection& c : goal_cells) {
    const auto cost = static_cast<float>(c.cost);
    Cell& cell = cells[c.cell];
    if (!current(cell) || cost < cell.cost) {
      cell.cost = cost;
      cell.bits = static_cast<std::uint16_t>((cell.bits & kKindMask) | stamp);  // no successor: the goal is next
      push(c.cell, cost, goal_estimate(c));
    }
  }

  std::array<std::ptrdiff_t, 8> offset{};
  for (std::size_t k = 0; k < 8; ++k) {
    offset[k] = kNeighbours[k].drow * static_cast<std::ptrdiff_t>(stride_) + kNeighbours[k].dcol;
  }
  // The step from `cell` (at col, row) into its neighbour k.
  const auto relax = [&](std::size_t cell, float here, int col, int row, std::size_t k, float length,
                         bool diagonal) {
    const std::size_t next = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(cell) + offset[k]);
    Cell& to = cells[next];
    const std::uint16_t bits = to.bits;
    if (!(bits & kFreeClass) || (diagonal && !(bits & kDiagonalOk))) return;
    const float cost = here + length * step_weight[bits & kLevelMask];
    if ((bits >> kGenerationShift) == generation && !(cost < to.cost)) return;
    to.cost = cost;
    to.bits = static_cast<std::uint16_t>((bits & kKindMask) | stamp | kHasSuccessor | ((7 - k) << kDirectionShift));
    push(next, cost, cost + remaining(col + kNeighbours[k].dcol, row + kNeighbours[k].drow));
  };

  // A* from the goal: a bucket holds the cells whose estimate of the whole
  // way lies in one cost unit. The estimate never falls along a step (the
  // bound is consistent), so a bucket feeds only itself and those after it.
  // Within a bucket cells are taken in any order, so one may be reached
  // again more cheaply after it was expanded: it is queued and expanded
  // again. Every cell whose estimate is below the best total found has been
  // expanded at its final cost when the loop ends, so the total is the least.
  double best_total = std::numeric_limits<double>::infinity();
  std::size_t best_cell = 0;
  std::size_t settled = 0;
  constexpr auto kDiagonal = static_cast<float>(kSqrt2);
  for (; queued > 0 && static_cast<double>(level) < best_total; ++level) {
    std::vector<Queued>& bucket = buckets_[level & bucket_mask];
    for (std::size_t i = 0; i < bucket.size(); ++i) {
      --queued;
      // The front is spread over the map and the loop waits on memory:
      // fetch the three rows around a cell a few entries ahead.
      if (i + kPrefetchAhead < bucket.size()) {
        const Cell* ahead = cells + bucket[i + kPrefetchAhead].cell;
        __builtin_prefetch(ahead - stride_, 1);
        __builtin_prefetch(ahead, 1);
        __builtin_prefetch(ahead + stride_, 1);
      }
      const Queued entry = bucket[i];
      const std::size_t cell = entry.cell;
      const float here = cells[cell].cost;
      if (here < entry.cost) continue;  // queued again at a lower cost since
      ++settled;
      if (cell >= start_box_first && cell <= start_box_last) {
        for (const Connection& c : start_cells) {
          if (c.cell == cell && here + c.cost < best_total) {
            best_total = here + c.cost;
            best_cell = cell;
          }
        }
      }
      const auto row = static_cast<int>(entry.cell / stride);
      const auto col = static_cast<int>(entry.cell - static_cast<std::uint32_t>(row) * stride);
      relax(cell, here, col, row, 1, 1.0f, false);
      relax(cell, here, col, row, 3, 1.0f, false);
      relax(cell, here, col, row, 4, 1.0f, false);
      relax(cell, here, col, row, 6, 1.0f, false);
      if (cells[cell].bits & kDiagonalOk) {
        relax(cell, here, col, row, 0, kDiagonal, true);
        relax(cell, here, col, row, 2, kDiagonal, true);
        relax(cell, here, col, row, 5, kDiagonal, true);
        relax(cell, here, col, row, 7, kDiagonal, true);
      }
    }
    bucket.clear();
  }
  return {best_total, best_cell, settled};
}

std::vector<Eigen::Vector2d> WavefrontPlanner::chain_from(std::size_t first_cell, const Eigen::Vector2d& start,
                                                          const Eigen::Vector2d& goal) const {
  std::vector<Eigen::Vector2d> chain{start};
  for (std::size_t cell = first_cell;;) {
    chain.push_back(padded_centre(cell));
    const std::uint16_t bits = cells_[cell].bits;
    if (!(bits & kHasSuccessor)) break;  // a goal cell
    const Neighbour& toward = kNeighbours[(bits >> kDirectionShift) & 7];
    cell = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(cell) +
                                    toward.drow * static_cast<std::ptrdiff_t>(stride_) + toward.dcol);
  }
  chain.push_back(goal);
  return chain;
}

// 1.5 walks the chain and puts the next waypoint where the line of sight
// from the last one ends. Here: the farthest chain point in sight (with the
// clearance), found by galloping then bisecting, so a long straight run
// costs a few segment checks rather than one per cell. Consecutive chain
// points are always in sight of each other.
std::vector<Eigen::Vector2d> WavefrontPlanner::waypoints_along(const std::vector<Eigen::Vector2d>& chain) const {
  const double required = parameters_.required_clearance();
  const std::size_t last = chain.size() - 1;
  std::vector<Eigen::Vector2d> waypoints{chain.front()};
  std::size_t from = 0;
  while (from < last) {
    const auto in_sight = [&](std::size_t to) { return clearance_.segment_keeps(chain[from], chain[to], required); };
    std::size_t seen = from + 1;
    if (in_sight(last)) {
      seen = last;
    } else {
      std::size_t hidden = last;
      for (std::size_t step = 1; seen + step < hidden; step *= 2) {
        if (!in_sight(seen + step)) {
          hidden = seen + step;
          break;
        }
        seen += step;
      }
      while (hidden - seen > 1) {
        const std::size_t middle = seen + (hidden - seen) / 2;
        (in_sight(middle) ? seen : hidden) = middle;
      }
    }
    waypoints.push_back(chain[seen]);
    from = seen;
  }
  tighten(waypoints);
  return waypoints;
}

// Waypoints on cell centres go round a corner up to a cell wide of it.
// Pull the string: each inner waypoint moves toward the line between its
// neighbours as far as both of its segments keep the clearance (bisection).
// A corner is rounded better by three waypoints than by one, so each inner
// waypoint first gets a companion on either side, and waypoints whose
// neighbours see each other go at the end. Every position taken has been
// checked, so the guarantee holds throughout; the length only decreases.
void WavefrontPlanner::tighten(std::vector<Eigen::Vector2d>& waypoints) const {
  constexpr int kSweeps = 30;
  constexpr int kBisections = 6;
  if (waypoints.size() < 3) return;
  const double required = parameters_.required_clearance();
  const auto keeps = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return clearance_.segment_keeps(a, b, required);
  };

  // Companions at these multiples of the clearance from the corner, at
  // most 40 % of the way to the next waypoint.
  constexpr std::array<double, 3> kCompanions{0.5, 1.0, 2.0};
  const auto companions = [&](const Eigen::Vector2d& corner, const Eigen::Vector2d& neighbour, bool outward,
                              std::vector<Eigen::Vector2d>& out) {
    const Eigen::Vector2d away = neighbour - corner;
    const double length = away.norm();
    if (!(length > 0.0)) return;
    for (std::size_t k = 0; k < kCompanions.size(); ++k) {
      const double distance = std::min(kCompanions[outward ? k : kCompanions.size() - 1 - k] * required, 0.4 * length);
      out.push_back(corner + away * (distance / length));
    }
  };
  std::vector<Eigen::Vector2d> loose{waypoints.front()};
  for (std::size_t i = 1; i + 1 < waypoints.size(); ++i) {
    companions(waypoints[i], waypoints[i - 1], false, loose);
    loose.push_back(waypoints[i]);
    companions(waypoints[i], waypoints[i + 1], true, loose);
  }
  loose.push_back(waypoints.back());

  // A waypoint is looked at again only when it or a neighbour moved more
  // than a hundredth of a cell in the last sweep.
  const double small = 0.01 * clearance_.resolution();
  std::vector<std::uint8_t> active(loose.size(), 1), moved(loose.size(), 0);
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    std::fill(moved.begin(), moved.end(), std::uint8_t{0});
    bool any = false;
    for (std::size_t i = 1; i + 1 < loose.size(); ++i) {
      if (!active[i]) continue;
      const Eigen::Vector2d a = loose[i - 1], here = loose[i], b = loose[i + 1];
      // Toward the nearest point of the line a-b, as far as both segments keep.
      const Eigen::Vector2d ab = b - a;
      const double t = std::clamp((here - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
      const Eigen::Vector2d toward = a + t * ab - here;
      if (toward.norm() < small) continue;
      double fits = 0.0, fails = 1.0;
      if (keeps(a, b)) {
        fits = 1.0;
      } else {
        for (int k = 0; k < kBisections; ++k) {
          const double middle = 0.5 * (fits + fails);
          const Eigen::Vector2d candidate = here + middle * toward;
          (keeps(a, candidate) && keeps(candidate, b) ? fits : fails) = middle;
        }
      }
      if (fits > 0.0) {
        loose[i] = here + fits * toward;
        if (fits * toward.norm() >= small) {
          moved[i] = 1;
          any = true;
        }
      }
    }
    if (!any) break;
    for (std::size_t i = 1; i + 1 < loose.size(); ++i) active[i] = moved[i - 1] | moved[i] | moved[i + 1];
  }

  waypoints.assign(1, loose.front());
  for (std::size_t i = 1; i < loose.size(); ++i) {
    const bool last = i + 1 == loose.size();
    if (!last && keeps(waypoints.back(), loose[i + 1])) continue;
    waypoints.push_back(loose[i]);
  }
}

std::string describe_failure(const PlanResult& result, const PlannerParameters& parameters) {
  if (result.found()) return {};
  char required[32];
  std::snprintf(required, sizeof required, "%.2f m", parameters.required_clearance());
  if (result.status == PlanStatus::unreachable) {
    return std::string("the goal cannot be reached: no path keeps ") + required +
           " (robot radius + safety) from every occupied or unknown cell";
  }
  const bool start = result.status == PlanStatus::start_invalid;
  const std::string what = start ? "start" : "goal";
  const EndpointState state = start ? result.start : result.goal;
  char clearance[32];
  std::snprintf(clearance, sizeof clearance, "%.2f m", start ? result.start_clearance_m : result.goal_clearance_m);
  switch (state) {
    case EndpointState::outside_map:
      return what + " is outside the map";
    case EndpointState::occupied:
      return what + " is in an occupied cell";
    case EndpointState::unknown:
      return what + " is in an unknown cell";
    case EndpointState::too_close:
      return what + " is " + clearance + " from an occupied or unknown cell, closer than " + required +
             " (robot radius + safety)";
    case EndpointState::cornered:
      return what + " keeps " + required + " but no cell centre within " + std::to_string(kConnectionRadius) +
             " cells of it can be reached keeping it";
    case EndpointState::ok:
      break;
  }
  return what + " cannot be used";
}

}  // namespace playerkit::wavefront
