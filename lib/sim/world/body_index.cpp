#include "sim/world/body_index.hpp"

#include <type_traits>

namespace playerkit::sim {

namespace {

constexpr double kIndexCellSize = 2.0;        // m: a few robots per cell
constexpr long long kMostIndexCells = 1 << 18;  // beyond: coarser cells
constexpr long long kMostCellsPerBody = 64;   // beyond: tested by every ray
// Farther than this (or not finite) a model is not gridded but tested by
// every query, so that one absurd pose cannot blow the grid up.
constexpr double kFarthestGridded = 1.0e6;  // m

bool grid_can_hold(const PlacedBody& shape) {
  const double reach = std::abs(shape.centre.x()) + std::abs(shape.centre.y()) + shape.bounding_radius;
  return reach < kFarthestGridded;  // false for NaN too
}

template <typename Listed>
void erase_listed(std::vector<Listed>& listed, ModelId id) {
  const auto found = std::find_if(listed.begin(), listed.end(), [id](const Listed& item) {
    if constexpr (std::is_same_v<Listed, ModelId>) {
      return item == id;
    } else {
      return item.id == id;
    }
  });
  if (found == listed.end()) return;
  *found = listed.back();
  listed.pop_back();
}

CellSlot slot_of(ModelId id, const IndexedBody& body) {
  // Rounded up, so that the float never makes a body look smaller.
  const auto reach = static_cast<float>(body.shape.bounding_radius);
  return {.id = id,
          .root = body.root,
          .x = body.shape.centre.x(),
          .y = body.shape.centre.y(),
          .reach = static_cast<double>(reach) < body.shape.bounding_radius
                       ? std::nextafter(reach, std::numeric_limits<float>::infinity())
                       : reach,
          .ranger_visible = body.ranger_visible};
}

}  // namespace

void BodyIndex::cover(const Eigen::Vector2d& low, const Eigen::Vector2d& high) {
  if (!(high.x() > low.x()) || !(high.y() > low.y())) return;
  rebuild(low, high);
}

BodyIndex::CellRange BodyIndex::range_around(const Eigen::Vector2d& centre, double radius) const {
  const auto cell_of = [this](double coordinate, double low) {
    return static_cast<int>(std::clamp(std::floor((coordinate - low) / cell_size_), -1.0e9, 1.0e9));
  };
  return {cell_of(centre.x() - radius, low_.x()), cell_of(centre.y() - radius, low_.y()),
          cell_of(centre.x() + radius, low_.x()), cell_of(centre.y() + radius, low_.y())};
}

void BodyIndex::put(ModelId id, const IndexedBody& body) {
  if (static_cast<std::size_t>(id) >= entries_.size()) entries_.resize(static_cast<std::size_t>(id) + 1);
  Entry& entry = entries_[static_cast<std::size_t>(id)];
  if (entry.listed) {
    // Most moves stay within the cells the model was listed in.
    if (!entry.oversized && entry.body.solid == body.solid && grid_can_hold(body.shape)) {
      const CellRange range = range_of(body);
      if (range.col0 == entry.cells.col0 && range.col1 == entry.cells.col1 && range.row0 == entry.cells.row0 &&
          range.row1 == entry.cells.row1 && on_grid(range)) {
        entry.body = body;
        if (body.solid) refresh_slots(id, entry);
        return;
      }
    }
    unlist(id, entry);
  }
  entry.body = body;
  list(id, entry);
}

void BodyIndex::remove(ModelId id) {
  if (!listed(id)) return;
  unlist(id, entries_[static_cast<std::size_t>(id)]);
}

void BodyIndex::list(ModelId id, Entry& entry) {
  entry.oversized = !grid_can_hold(entry.body.shape);
  if (!entry.oversized) {
    // Before this entry counts as listed: a rebuild lists what is listed.
    if (columns_ == 0 || !on_grid(range_of(entry.body))) grow_to(entry.body);
    entry.cells = range_of(entry.body);
    const long long cells = static_cast<long long>(entry.cells.col1 - entry.cells.col0 + 1) *
                            static_cast<long long>(entry.cells.row1 - entry.cells.row0 + 1);
    entry.oversized = cells > kMostCellsPerBody;
  }
  entry.listed = true;
  if (entry.body.solid) ++solid_count_;
  if (entry.oversized) {
    oversized_.push_back(id);
    return;
  }
  const CellSlot slot = slot_of(id, entry.body);
  for (int row = entry.cells.row0; row <= entry.cells.row1; ++row) {
    for (int col = entry.cells.col0; col <= entry.cells.col1; ++col) {
      const std::size_t cell = cell_index(col, row);
      if (entry.body.solid) {
        solid_cells_[cell].push_back(slot);
      } else {
        point_cells_[cell].push_back(id);
      }
    }
  }
}

void BodyIndex::refresh_slots(ModelId id, const Entry& entry) {
  const CellSlot slot = slot_of(id, entry.body);
  for (int row = entry.cells.row0; row <= entry.cells.row1; ++row) {
    for (int col = entry.cells.col0; col <= entry.cells.col1; ++col) {
      for (CellSlot& listed : solid_cells_[cell_index(col, row)]) {
        if (listed.id == id) listed = slot;
      }
    }
  }
}

void BodyIndex::unlist(ModelId id, Entry& entry) {
  entry.listed = false;
  if (entry.body.solid) --solid_count_;
  if (entry.oversized) {
    erase_listed(oversized_, id);
    return;
  }
  for (int row = entry.cells.row0; row <= entry.cells.row1; ++row) {
    for (int col = entry.cells.col0; col <= entry.cells.col1; ++col) {
      const std::size_t cell = cell_index(col, row);
      if (entry.body.solid) {
        erase_listed(solid_cells_[cell], id);
      } else {
        erase_listed(point_cells_[cell], id);
      }
    }
  }
}

void BodyIndex::grow_to(const IndexedBody& body) {
  const Eigen::Vector2d reach = Eigen::Vector2d::Constant(body.shape.bounding_radius);
  Eigen::Vector2d low = body.shape.centre - reach;
  Eigen::Vector2d high = body.shape.centre + reach;
  if (columns_ > 0) {
    low = low.cwiseMin(low_);
    high = high.cwiseMax(low_ + cell_size_ * Eigen::Vector2d(columns_, rows_));
  }
  // Room to move: a robot leaving the grid should not rebuild it every step.
  const Eigen::Vector2d margin = ((high - low) / 4.0).cwiseMax(Eigen::Vector2d::Constant(4.0 * kIndexCellSize));
  rebuild(low - margin, high + margin);
}

void BodyIndex::rebuild(const Eigen::Vector2d& low, const Eigen::Vector2d& high) {
  const Eigen::Vector2d span = high - low;
  cell_size_ = kIndexCellSize;
  const auto count = [&](double extent) { return static_cast<long long>(std::ceil(extent / cell_size_)) + 1; };
  while (count(span.x()) * count(span.y()) > kMostIndexCells) cell_size_ *= 2.0;
  low_ = low;
  columns_ = static_cast<int>(count(span.x()));
  rows_ = static_cast<int>(count(span.y()));
  const std::size_t cells = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
  solid_cells_.assign(cells, {});
  point_cells_.assign(cells, {});
  oversized_.clear();
  solid_count_ = 0;
  for (std::size_t id = 0; id < entries_.size(); ++id) {
    Entry& entry = entries_[id];
    if (!entry.listed) continue;
    // Every listed model fits the new grid, so list() will not grow it again.
    list(static_cast<ModelId>(id), entry);
  }
}

}  // namespace playerkit::sim
