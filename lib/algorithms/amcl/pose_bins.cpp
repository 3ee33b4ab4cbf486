#include "algorithms/amcl/pose_bins.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace playerkit::amcl {

PoseBinning::PoseBinning(double cell_size, double angle_size)
    : cell_size_(cell_size), angle_size_(angle_size) {
  if (!(cell_size > 0.0) || !(angle_size > 0.0)) {
    throw std::invalid_argument("PoseBinning: bin sizes must be positive");
  }
  // Round the bin count so the circle splits evenly; at least one bin.
  yaw_bin_count_ = std::max(1, static_cast<int>(std::lround(2.0 * std::numbers::pi / angle_size)));
  angle_size_ = 2.0 * std::numbers::pi / yaw_bin_count_;
}

PoseBin PoseBinning::bin_of(const geometry::Pose2& pose) const {
  int yaw_bin = static_cast<int>(std::floor((pose.yaw + std::numbers::pi) / angle_size_));
  // A normalized yaw lands in range (or on the count, at pi): no division.
  if (yaw_bin == yaw_bin_count_) {
    yaw_bin = 0;
  } else if (yaw_bin < 0 || yaw_bin > yaw_bin_count_) {
    yaw_bin %= yaw_bin_count_;
    if (yaw_bin < 0) yaw_bin += yaw_bin_count_;
  }
  return {static_cast<std::int32_t>(std::floor(pose.x / cell_size_)),
          static_cast<std::int32_t>(std::floor(pose.y / cell_size_)), yaw_bin};
}

namespace {

// The yaw offsets of a bin's neighbours: -1, 0 and +1, except that with
// fewer than three yaw bins -1 and +1 wrap onto the same bin (or the bin
// itself), so each distinct offset is listed once.
std::size_t yaw_offsets(int yaw_bin_count, std::array<int, 3>& offsets) {
  if (yaw_bin_count == 1) {
    offsets = {0, 0, 0};
    return 1;
  }
  if (yaw_bin_count == 2) {
    offsets = {0, 1, 0};
    return 2;
  }
  offsets = {-1, 0, 1};
  return 3;
}

// yaw + offset round the circle; yaw is a bin's (in range), |offset| <= 1.
int wrap_yaw(int yaw, int offset, int yaw_bin_count) {
  const int wrapped = yaw + offset;
  if (wrapped < 0) return wrapped + yaw_bin_count;
  return wrapped >= yaw_bin_count ? wrapped - yaw_bin_count : wrapped;
}

}  // namespace

std::size_t PoseBinning::neighbours(const PoseBin& bin, std::array<PoseBin, 26>& out) const {
  std::array<int, 3> offsets{};
  const std::size_t offset_count = yaw_offsets(yaw_bin_count_, offsets);
  std::size_t count = 0;
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (std::size_t k = 0; k < offset_count; ++k) {
        const int dyaw = offsets[k];
        if (dx == 0 && dy == 0 && dyaw == 0) continue;
        out[count++] = {bin.x + dx, bin.y + dy, wrap_yaw(bin.yaw, dyaw, yaw_bin_count_)};
      }
    }
  }
  return count;
}

std::size_t PoseBinning::forward_neighbours(const PoseBin& bin, std::array<PoseBin, 13>& out) const {
  std::array<int, 3> offsets{};
  const std::size_t offset_count = yaw_offsets(yaw_bin_count_, offsets);
  std::size_t count = 0;
  for (int dx = 0; dx <= 1; ++dx) {
    for (int dy = dx == 0 ? 0 : -1; dy <= 1; ++dy) {
      for (std::size_t k = 0; k < offset_count; ++k) {
        const int dyaw = offsets[k];
        // With (dx, dy) = (0, 0), only forward in yaw; with two yaw bins
        // the offset 1 is its own opposite and counts as forward.
        if (dx == 0 && dy == 0 && dyaw <= 0) continue;
        out[count++] = {bin.x + dx, bin.y + dy, wrap_yaw(bin.yaw, dyaw, yaw_bin_count_)};
      }
    }
  }
  return count;
}

std::uint64_t PoseBinning::key(const PoseBin& bin) {
  // 24 bits for each of x and y (cells of any sensible size cover far more
  // than any map) and 16 for yaw.
  const auto field = [](std::int32_t value, int bits) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(value)) & ((1ull << bits) - 1);
  };
  return field(bin.x, 24) | (field(bin.y, 24) << 24) | (field(bin.yaw, 16) << 48);
}

BinTable::BinTable(std::size_t max_bins) { reserve(max_bins); }

namespace {

// Keep the load factor at or under one half so probes stay short.
std::size_t capacity_for(std::size_t max_bins) { return std::bit_ceil(std::max<std::size_t>(16, 2 * max_bins)); }

}  // namespace

void BinTable::reserve(std::size_t max_bins) {
  const std::size_t capacity = capacity_for(max_bins);
  if (capacity <= slots_.size()) return;
  slots_.assign(capacity, Slot{});
  used_.clear();
  mask_ = capacity - 1;
  shift_ = 64 - std::countr_zero(capacity);
  size_ = 0;
}

void BinTable::reset(std::size_t max_bins) {
  const std::size_t capacity = capacity_for(max_bins);
  if (slots_.size() > 4 * capacity) {  // shrink: start afresh
    slots_.clear();
    used_.clear();
    size_ = 0;
  } else {
    clear();
  }
  reserve(max_bins);
}

void BinTable::clear() {
  for (const std::uint32_t slot : used_) slots_[slot].index = not_found;
  used_.clear();
  size_ = 0;
}

std::size_t BinTable::slot_of(std::uint64_t key) const {
  std::size_t slot = home_slot(key);
  while (slots_[slot].index != not_found && slots_[slot].key != key) slot = (slot + 1) & mask_;
  return slot;
}

std::pair<std::uint32_t, bool> BinTable::insert(std::uint64_t key) {
  if (2 * (size_ + 1) > slots_.size()) {
    // Grow (rare: only if more bins appear than reserved for) by rehashing.
    const std::vector<Slot> old_slots = std::move(slots_);
    slots_.clear();
    const std::size_t old_size = size_;
    reserve(std::max<std::size_t>(16, old_slots.size()));
    for (const Slot& old : old_slots) {
      if (old.index == not_found) continue;
      const std::size_t slot = slot_of(old.key);
      slots_[slot] = old;
      used_.push_back(static_cast<std::uint32_t>(slot));
    }
    size_ = old_size;
  }
  const std::size_t slot = slot_of(key);
  Slot& found = slots_[slot];
  if (found.index != not_found) return {found.index, false};
  found = {key, static_cast<std::uint32_t>(size_++)};
  used_.push_back(static_cast<std::uint32_t>(slot));
  return {found.index, true};
}

std::uint32_t BinTable::find(std::uint64_t key) const {
  if (slots_.empty()) return not_found;
  return slots_[slot_of(key)].index;
}

bool DenseBinGrid::reset(const PoseBin& low, const PoseBin& high, int yaw_bin_count, std::size_t max_cells) {
  const double columns = static_cast<double>(high.x) - low.x + 1.0;
  const double rows = static_cast<double>(high.y) - low.y + 1.0;
  if (!(columns >= 1.0 && rows >= 1.0 && yaw_bin_count >= 1) ||
      columns * rows * yaw_bin_count > static_cast<double>(max_cells)) {
    return false;
  }
  low_ = low;
  high_ = high;
  rows_ = static_cast<std::size_t>(rows);
  yaws_ = static_cast<std::size_t>(yaw_bin_count);
  cells_.assign(static_cast<std::size_t>(columns) * rows_ * yaws_, BinTable::not_found);
  return true;
}

}  // namespace playerkit::amcl
