#pragma once
// Internal: the scene's broad phase. A uniform grid of cells (2 m, coarser
// only in a vast world) over the map and every model; each cell lists the
// models whose bounding circle reaches into it. A ray visits only the cells
// it crosses, nearest first, and a collision or fiducial query only the
// cells around it, so the cost of either does not grow with the number of
// models in the world. Models far off the grid make it grow (rebuilt, so
// rarely); a body too large for a few cells is tested by every ray instead.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "sim/world/body_geometry.hpp"
#include "sim/world/model_spec.hpp"

namespace playerkit::sim {

// What a ray or a collision test needs of a model, without the rest of its
// SceneModel: kept compact so that the tests stay in cache.
struct IndexedBody {
  PlacedBody shape;              // bounding_radius 0 and !solid for a model without a body
  ModelId root = kNoModel;
  bool solid = false;            // has a body (rays and collisions meet it)
  bool ranger_visible = false;   // ranger return >= 0
  bool obstacle = false;
};

// A solid body as its cells list it: enough to reject most rays without
// looking further (the bounding circle, the tree, ranger visibility).
struct CellSlot {
  ModelId id = kNoModel;
  ModelId root = kNoModel;
  double x = 0.0, y = 0.0;  // the body's centre
  float reach = 0.0f;       // its bounding radius, rounded up
  bool ranger_visible = false;
};

class BodyIndex {
 public:
  // Starts the grid over this rectangle (the map); it grows as models need.
  void cover(const Eigen::Vector2d& low, const Eigen::Vector2d& high);

  // Lists a model (again, where it now is); `remove` unlists it.
  void put(ModelId id, const IndexedBody& body);
  void remove(ModelId id);
  [[nodiscard]] const IndexedBody& body(ModelId id) const { return entries_[static_cast<std::size_t>(id)].body; }
  [[nodiscard]] bool listed(ModelId id) const {
    return static_cast<std::size_t>(id) < entries_.size() && entries_[static_cast<std::size_t>(id)].listed;
  }
  [[nodiscard]] bool has_solid_bodies() const { return solid_count_ > 0; }

  // Solid bodies too large to list cell by cell; every ray tests them.
  [[nodiscard]] std::span<const ModelId> oversized() const { return oversized_; }

  // Visits the cells a ray crosses within `length` (unit `direction`),
  // nearest first, with the solid bodies listed there (a span of CellSlot)
  // and the distance at which the ray leaves the cell; stops when `visit`
  // returns false.
  template <typename Visit>
  void along_ray(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, double length, Visit&& visit) const;

  // Visits every listed model (solid or not) whose bounding box reaches the
  // square of half-side `radius` around `centre`, oversized ones included;
  // a model may be visited more than once.
  template <typename Visit>
  void near(const Eigen::Vector2d& centre, double radius, Visit&& visit) const;
  // The same for solid bodies only, as the CellSlot their cells list them
  // by (oversized ones too).
  template <typename Visit>
  void near_solid(const Eigen::Vector2d& centre, double radius, Visit&& visit) const;

 private:
  struct CellRange {
    int col0 = 0, row0 = 0, col1 = -1, row1 = -1;
  };
  struct Entry {
    IndexedBody body;
    bool listed = false;
    bool oversized = false;
    CellRange cells;
  };

  [[nodiscard]] std::size_t cell_index(int col, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(col);
  }
  // The cells a disc touches, not clipped to the grid.
  [[nodiscard]] CellRange range_around(const Eigen::Vector2d& centre, double radius) const;
  [[nodiscard]] CellRange range_of(const IndexedBody& body) const {
    return range_around(body.shape.centre, body.shape.bounding_radius);
  }
  // visit_cell(index) for every grid cell the disc touches.
  template <typename VisitCell>
  void for_cells_near(const Eigen::Vector2d& centre, double radius, VisitCell&& visit_cell) const;
  [[nodiscard]] bool on_grid(const CellRange& range) const {
    return range.col0 >= 0 && range.row0 >= 0 && range.col1 < columns_ && range.row1 < rows_;
  }
  void list(ModelId id, Entry& entry);
  void unlist(ModelId id, Entry& entry);
  void grow_to(const IndexedBody& body);
  void rebuild(const Eigen::Vector2d& low, const Eigen::Vector2d& high);
  void refresh_slots(ModelId id, const Entry& entry);

  std::vector<Entry> entries_;
  std::vector<std::vector<CellSlot>> solid_cells_;  // bodies: rays, collisions
  std::vector<std::vector<ModelId>> point_cells_;  // bodiless models: found by near() only
  std::vector<ModelId> oversized_;
  std::size_t solid_count_ = 0;
  Eigen::Vector2d low_ = Eigen::Vector2d::Zero();
  double cell_size_ = 2.0;
  int columns_ = 0;
  int rows_ = 0;
};

template <typename Visit>
void BodyIndex::along_ray(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, double length,
                          Visit&& visit) const {
  if (columns_ == 0 || !(length > 0.0)) return;
  const Eigen::Vector2d high = low_ + cell_size_ * Eigen::Vector2d(columns_, rows_);
  // Clip the ray to the grid: nothing is listed outside it.
  double enter = 0.0;
  double leave = length;
  for (int axis = 0; axis < 2; ++axis) {
    if (direction[axis] == 0.0) {
      if (origin[axis] < low_[axis] || origin[axis] > high[axis]) return;
      continue;
    }
    double near_side = (low_[axis] - origin[axis]) / direction[axis];
    double far_side = (high[axis] - origin[axis]) / direction[axis];
    if (near_side > far_side) std::swap(near_side, far_side);
    enter = std::max(enter, near_side);
    leave = std::min(leave, far_side);
  }
  if (enter > leave) return;

  const Eigen::Vector2d start = origin + enter * direction;
  const int limits[2] = {columns_, rows_};
  int cell[2];
  int step[2];
  double next_border[2];  // distance along the ray to the next cell border, per axis
  double border_spacing[2];
  constexpr double infinity = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 2; ++axis) {
    const double cells = std::floor((start[axis] - low_[axis]) / cell_size_);
    cell[axis] = static_cast<int>(std::clamp(cells, 0.0, static_cast<double>(limits[axis] - 1)));
    if (direction[axis] > 0.0) {
      step[axis] = 1;
      next_border[axis] = (low_[axis] + (cell[axis] + 1) * cell_size_ - origin[axis]) / direction[axis];
      border_spacing[axis] = cell_size_ / direction[axis];
    } else if (direction[axis] < 0.0) {
      step[axis] = -1;
      next_border[axis] = (low_[axis] + cell[axis] * cell_size_ - origin[axis]) / direction[axis];
      border_spacing[axis] = -cell_size_ / direction[axis];
    } else {
      step[axis] = 0;
      next_border[axis] = infinity;
      border_spacing[axis] = infinity;
    }
  }
  for (;;) {
    const int axis = next_border[0] <= next_border[1] ? 0 : 1;
    const double exit = std::min(next_border[axis], leave);
    const std::vector<CellSlot>& listed_here = solid_cells_[cell_index(cell[0], cell[1])];
    if (!visit(std::span<const CellSlot>(listed_here), exit)) return;
    if (exit >= leave) return;
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= limits[axis]) return;
    next_border[axis] += border_spacing[axis];
  }
}

template <typename Visit>
void BodyIndex::near_solid(const Eigen::Vector2d& centre, double radius, Visit&& visit) const {
  for (const ModelId id : oversized_) {
    const IndexedBody& indexed = body(id);
    if (!indexed.solid) continue;
    visit(CellSlot{.id = id,
                   .root = indexed.root,
                   .x = indexed.shape.centre.x(),
                   .y = indexed.shape.centre.y(),
                   .reach = std::numeric_limits<float>::infinity(),  // the exact test decides
                   .ranger_visible = indexed.ranger_visible});
  }
  for_cells_near(centre, radius, [&](std::size_t cell) {
    for (const CellSlot& slot : solid_cells_[cell]) visit(slot);
  });
}

template <typename Visit>
void BodyIndex::near(const Eigen::Vector2d& centre, double radius, Visit&& visit) const {
  for (const ModelId id : oversized_) visit(id);
  for_cells_near(centre, radius, [&](std::size_t cell) {
    for (const CellSlot& slot : solid_cells_[cell]) visit(slot.id);
    for (const ModelId id : point_cells_[cell]) visit(id);
  });
}

template <typename VisitCell>
void BodyIndex::for_cells_near(const Eigen::Vector2d& centre, double radius, VisitCell&& visit_cell) const {
  if (columns_ == 0) return;
  const CellRange range = range_around(centre, radius);
  const int col0 = std::max(range.col0, 0);
  const int col1 = std::min(range.col1, columns_ - 1);
  const int row0 = std::max(range.row0, 0);
  const int row1 = std::min(range.row1, rows_ - 1);
  for (int row = row0; row <= row1; ++row) {
    for (int col = col0; col <= col1; ++col) visit_cell(cell_index(col, row));
  }
}

}  // namespace playerkit::sim
