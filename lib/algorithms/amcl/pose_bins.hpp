#pragma once
// A 3-D histogram over poses (x, y, yaw): the bins KLD-sampling counts and
// the cells the pose-estimate clustering joins. Yaw bins wrap around the
// circle. BinTable maps bin keys to dense indices without allocating per
// insertion (open addressing over a reserved array), so counting bins for
// thousands of particles per update costs no heap traffic.

#include "algorithms/geometry/pose2.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace playerkit::amcl {

struct PoseBin {
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::int32_t yaw = 0;  // in [0, yaw_bin_count)
  friend bool operator==(const PoseBin&, const PoseBin&) = default;
};

class PoseBinning {
 public:
  PoseBinning(double cell_size, double angle_size);

  PoseBin bin_of(const geometry::Pose2& pose) const;
  int yaw_bin_count() const { return yaw_bin_count_; }
  // The 26 bins around `bin` (fewer if the yaw circle has under 3 bins),
  // yaw wrapping around the circle; written into `out`, count returned.
  std::size_t neighbours(const PoseBin& bin, std::array<PoseBin, 26>& out) const;
  // Half of them: of each two opposite offsets, the one that goes forward
  // (in x, else in y, else in yaw). Every touching pair of bins is then one
  // bin's forward neighbour, so finding touching bins needs only these.
  std::size_t forward_neighbours(const PoseBin& bin, std::array<PoseBin, 13>& out) const;

  static std::uint64_t key(const PoseBin& bin);

 private:
  double cell_size_;
  double angle_size_;
  int yaw_bin_count_;
};

class BinTable {
 public:
  static constexpr std::uint32_t not_found = 0xffffffffu;

  // Room for `max_bins` distinct bins without growing.
  explicit BinTable(std::size_t max_bins = 0);
  void reserve(std::size_t max_bins);
  // Empties the table (in time proportional to the bins it held) and sizes
  // it for `max_bins`: it grows, or shrinks when four times too big, so
  // that a table once sized for a global search's particles does not stay
  // large (and its lookups spread out) while tracking.
  void reset(std::size_t max_bins);
  void clear();

  // Dense index of the bin (0, 1, 2, ... in first-insertion order) and whether
  // it was new.
  std::pair<std::uint32_t, bool> insert(std::uint64_t key);
  std::uint32_t find(std::uint64_t key) const;
  std::size_t size() const { return size_; }
  // Asks for the key's home slot to be brought into the cache: a loop over
  // many bins waits on memory unless it asks a few keys ahead.
  void prefetch(std::uint64_t key) const {
    if (!slots_.empty()) __builtin_prefetch(&slots_[home_slot(key)]);
  }

 private:
  std::size_t home_slot(std::uint64_t key) const {
    // Fibonacci hashing: the top bits of key * 2^64/phi, which every bit of
    // the key moves. (The low bits, which an earlier version took, never
    // saw the yaw at the top of the key: all 36 yaw bins of a cell shared a
    // home slot, and a global search's lookups probed dozens of slots.)
    return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> shift_);
  }
  std::size_t slot_of(std::uint64_t key) const;

  // Key and index side by side: a probe touches one cache line, not two.
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t index = not_found;  // not_found marks an empty slot
  };
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> used_;  // the slots holding a bin
  std::size_t mask_ = 0;
  int shift_ = 64;  // 64 - log2(capacity)
  std::size_t size_ = 0;
};

// Bin indices in an array over the box the bins span (every yaw bin): no
// hashing, and a bin's neighbours lie next to it in memory. For bins that
// fill much of their box, as a global search's do; BinTable otherwise.
class DenseBinGrid {
 public:
  // Sizes the grid for the cells from `low` to `high` (x and y; yaw is
  // ignored) and empties it. False, with nothing done, when that box holds
  // more than max_cells bins.
  bool reset(const PoseBin& low, const PoseBin& high, int yaw_bin_count, std::size_t max_cells);

  // The index stored for a bin inside the box (BinTable::not_found if none).
  std::uint32_t& at(const PoseBin& bin) { return cells_[offset(bin)]; }
  // Calls visit(bin, index) for every bin stored, in memory order: x, then
  // y, then yaw.
  template <typename Visit>
  void for_each(Visit&& visit) const {
    std::size_t offset = 0;
    for (std::int32_t x = low_.x; x <= high_.x; ++x) {
      for (std::int32_t y = low_.y; y <= high_.y; ++y) {
        for (std::size_t yaw = 0; yaw < yaws_; ++yaw, ++offset) {
          if (cells_[offset] != BinTable::not_found) visit(PoseBin{x, y, static_cast<std::int32_t>(yaw)}, cells_[offset]);
        }
      }
    }
  }
  // The same, or not_found for a bin outside the box.
  std::uint32_t find(const PoseBin& bin) const {
    if (bin.x < low_.x || bin.x > high_.x || bin.y < low_.y || bin.y > high_.y) return BinTable::not_found;
    return cells_[offset(bin)];
  }

 private:
  std::size_t offset(const PoseBin& bin) const {
    return (static_cast<std::size_t>(bin.x - low_.x) * rows_ + static_cast<std::size_t>(bin.y - low_.y)) * yaws_ +
           static_cast<std::size_t>(bin.yaw);
  }

  PoseBin low_{}, high_{};
  std::size_t rows_ = 0, yaws_ = 0;
  std::vector<std::uint32_t> cells_;
};

}  // namespace playerkit::amcl
