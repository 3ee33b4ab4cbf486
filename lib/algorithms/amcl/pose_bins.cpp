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
        const int yaw = ((bin.yaw + dyaw) % yaw_bin_count_ + yaw_bin_count_) % yaw_bin_count_;
        out[count++] = {bin.x + dx, bin.y + dy, yaw};
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
        const int yaw = ((bin.yaw + dyaw) % yaw_bin_count_ + yaw_bin_count_) % yaw_bin_count_;
        out[count++] = {bin.x + dx, bin.y + dy, yaw};
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
  if (capacity <= keys_.size()) return;
  keys_.assign(capacity, 0);
  indices_.assign(capacity, not_found);
  used_.clear();
  mask_ = capacity - 1;
  size_ = 0;
}

void BinTable::reset(std::size_t max_bins) {
  const std::size_t capacity = capacity_for(max_bins);
  if (keys_.size() > 4 * capacity) {  // shrink: start afresh
    keys_.clear();
    indices_.clear();
    used_.clear();
    size_ = 0;
  } else {
    clear();
  }
  reserve(max_bins);
}

void BinTable::clear() {
  for (const std::uint32_t slot : used_) indices_[slot] = not_found;
  used_.clear();
  size_ = 0;
}

std::size_t BinTable::slot_of(std::uint64_t key) const {
  // A multiplicative (Fibonacci) hash spreads neighbouring bins apart.
  std::uint64_t h = key * 0x9e3779b97f4a7c15ull;
  h ^= h >> 29;
  std::size_t slot = static_cast<std::size_t>(h) & mask_;
  while (indices_[slot] != not_found && keys_[slot] != key) slot = (slot + 1) & mask_;
  return slot;
}

std::pair<std::uint32_t, bool> BinTable::insert(std::uint64_t key) {
  if (2 * (size_ + 1) > keys_.size()) {
    // Grow (rare: only if more bins appear than reserved for) by rehashing.
    std::vector<std::uint64_t> old_keys = std::move(keys_);
    std::vector<std::uint32_t> old_indices = std::move(indices_);
    keys_.clear();
    indices_.clear();
    const std::size_t old_size = size_;
    reserve(std::max<std::size_t>(16, old_keys.size()));
    for (std::size_t i = 0; i < old_keys.size(); ++i) {
      if (old_indices[i] == not_found) continue;
      const std::size_t slot = slot_of(old_keys[i]);
      keys_[slot] = old_keys[i];
      indices_[slot] = old_indices[i];
      used_.push_back(static_cast<std::uint32_t>(slot));
    }
    size_ = old_size;
  }
  const std::size_t slot = slot_of(key);
  if (indices_[slot] != not_found) return {indices_[slot], false};
  keys_[slot] = key;
  indices_[slot] = static_cast<std::uint32_t>(size_++);
  used_.push_back(static_cast<std::uint32_t>(slot));
  return {indices_[slot], true};
}

std::uint32_t BinTable::find(std::uint64_t key) const {
  if (keys_.empty()) return not_found;
  return indices_[slot_of(key)];
}

}  // namespace playerkit::amcl
