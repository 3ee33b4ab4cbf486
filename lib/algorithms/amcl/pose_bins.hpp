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

 private:
  std::size_t slot_of(std::uint64_t key) const;

  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> indices_;  // not_found marks an empty slot
  std::vector<std::uint32_t> used_;     // the slots holding a bin
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace playerkit::amcl
