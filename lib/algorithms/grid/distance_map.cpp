#include "algorithms/grid/distance_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>

namespace playerkit::grid {
namespace {

// Felzenszwalb & Huttenlocher (2012), "Distance Transforms of Sampled
// Functions": the exact squared distance transform is separable, so it is a
// 1-D pass down every column followed by a 1-D pass along every row.
//
// The column pass on a binary image is just "distance to the nearest occupied
// cell in this column", which two sweeps over whole rows produce while reading
// memory in order. The row pass is the lower envelope of parabolas
// f(q) + (x - q)^2, which needs the general algorithm.
//
// Distances are clamped at `cap` cells (at least max_distance, so nothing
// below the cap is changed): the envelope stays finite without any infinity
// arithmetic, and min(true distance, cap) is exactly what the caller keeps.
class LowerEnvelope {
 public:
  explicit LowerEnvelope(int length)
      : apex_(static_cast<std::size_t>(length)), boundary_(static_cast<std::size_t>(length) + 1) {}

  // squared[q] in, squared distance transform of the row out (in place).
  void transform(std::span<double> squared) {
    const int n = static_cast<int>(squared.size());
    if (n == 0) return;
    constexpr double infinity = std::numeric_limits<double>::infinity();
    input_.assign(squared.begin(), squared.end());
    int last = 0;  // index of the rightmost parabola in the envelope
    apex_[0] = 0;
    boundary_[0] = -infinity;
    boundary_[1] = infinity;
    for (int q = 1; q < n; ++q) {
      double crossing = intersection(q, apex_[static_cast<std::size_t>(last)]);
      while (crossing <= boundary_[static_cast<std::size_t>(last)]) {
        --last;
        crossing = intersection(q, apex_[static_cast<std::size_t>(last)]);
      }
      ++last;
      apex_[static_cast<std::size_t>(last)] = q;
      boundary_[static_cast<std::size_t>(last)] = crossing;
      boundary_[static_cast<std::size_t>(last) + 1] = infinity;
    }
    int segment = 0;
    for (int q = 0; q < n; ++q) {
      while (boundary_[static_cast<std::size_t>(segment) + 1] < q) ++segment;
      const int apex = apex_[static_cast<std::size_t>(segment)];
      const double offset = q - apex;
      squared[static_cast<std::size_t>(q)] = offset * offset + input_[static_cast<std::size_t>(apex)];
    }
  }

 private:
  // Where the parabola rooted at q overtakes the one rooted at p (p < q).
  double intersection(int q, int p) const {
    const double fq = input_[static_cast<std::size_t>(q)] + double(q) * q;
    const double fp = input_[static_cast<std::size_t>(p)] + double(p) * p;
    return (fq - fp) / (2.0 * (q - p));
  }

  std::vector<double> input_;
  std::vector<int> apex_;
  std::vector<double> boundary_;
};

}  // namespace

DistanceMap::DistanceMap(const OccupancyGrid& grid, double max_distance, DistanceTo sources)
    : width_(grid.width()),
      height_(grid.height()),
      resolution_(grid.resolution()),
      origin_(grid.origin()),
      max_distance_(max_distance) {
  if (!(max_distance >= 0.0)) {
    throw std::invalid_argument("DistanceMap: max_distance must be non-negative");
  }
  if (grid.empty()) return;

  // Any true distance is below width + height cells, so a larger cap never
  // changes an answer; it only keeps the arithmetic bounded.
  const double span_cells = double(width_) + double(height_) + 1.0;
  const double cap_cells = std::min(std::ceil(max_distance / resolution_) + 1.0, span_cells);
  const auto cap = static_cast<std::int32_t>(cap_cells);

  const auto w = static_cast<std::size_t>(width_);
  const auto h = static_cast<std::size_t>(height_);
  std::vector<std::int32_t> column_distance(w * h);

  const auto is_source = [sources](CellState state) {
    return sources == DistanceTo::occupied ? state == CellState::occupied : state != CellState::free;
  };

  // Upward sweep: distance to the nearest source cell at or below, per column.
  std::vector<std::int32_t> running(w, cap);
  for (std::size_t row = 0; row < h; ++row) {
    for (std::size_t col = 0; col < w; ++col) {
      const bool source = is_source(grid.at(static_cast<int>(col), static_cast<int>(row)));
      running[col] = source ? 0 : std::min(running[col] + 1, cap);
      column_distance[row * w + col] = running[col];
    }
  }
  // Downward sweep: nearest source cell at or above, keeping the smaller.
  std::fill(running.begin(), running.end(), cap);
  for (std::size_t row = h; row-- > 0;) {
    for (std::size_t col = 0; col < w; ++col) {
      std::int32_t& distance = column_distance[row * w + col];
      running[col] = distance == 0 ? 0 : std::min(running[col] + 1, cap);
      distance = std::min(distance, running[col]);
    }
  }

  // Along a row only the cells below the cap matter, and only within the
  // cap of them: a cell farther than that from every one stays at the cap,
  // and parabolas that far apart cannot meet below it. So the row pass runs
  // on stretches around the cells below the cap (split where two of them are
  // more than twice the cap apart), and the rest of the row is the cap. In
  // a large map most of every row is open hall or unmapped outside.
  const float max_distance_f = static_cast<float>(max_distance_);
  const auto to_metres = [&](double squared_cells) {
    return std::min(static_cast<float>(std::sqrt(squared_cells) * resolution_), max_distance_f);
  };
  const double cap_squared = double(cap) * cap;
  distances_.assign(w * h, to_metres(cap_squared));
  LowerEnvelope envelope(width_);
  std::vector<double> squared(w);
  const auto reach = static_cast<std::size_t>(cap);
  for (std::size_t row = 0; row < h; ++row) {
    const std::int32_t* distance = &column_distance[row * w];
    float* out = &distances_[row * w];
    std::size_t col = 0;
    while (true) {
      while (col < w && distance[col] >= cap) ++col;
      if (col == w) break;
      const std::size_t begin = col > reach ? col - reach : 0;
      std::size_t last = col;  // the last cell below the cap in this stretch
      for (++col; col < w && col - last <= 2 * reach; ++col) {
        if (distance[col] < cap) last = col;
      }
      const std::size_t end = std::min(w, last + reach + 1);
      const std::span<double> stretch(squared.data(), end - begin);
      for (std::size_t c = begin; c < end; ++c) {
        const double d = distance[c];
        stretch[c - begin] = d * d;
      }
      envelope.transform(stretch);
      for (std::size_t c = begin; c < end; ++c) out[c] = to_metres(stretch[c - begin]);
    }
  }
}

double DistanceMap::at_world(const Eigen::Vector2d& point) const {
  if (distances_.empty()) return max_distance_;
  const Eigen::Vector2d cells = (point - origin_) / resolution_;
  // Compare as doubles first so far-away points cannot overflow an int.
  if (!(cells.x() >= 0.0 && cells.y() >= 0.0 && cells.x() < width_ && cells.y() < height_)) {
    return max_distance_;
  }
  return at(static_cast<int>(cells.x()), static_cast<int>(cells.y()));
}

}  // namespace playerkit::grid
