#include "algorithms/amcl/pose_bins.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <set>
#include <tuple>
#include <vector>

namespace playerkit::amcl {
namespace pose_bins_test {

constexpr double pi = std::numbers::pi;

TEST(PoseBinning, BinsByFloorAndWrapsYaw) {
  const PoseBinning binning(0.5, pi / 18);  // 36 yaw bins
  EXPECT_EQ(binning.yaw_bin_count(), 36);
  EXPECT_EQ(binning.bin_of({0.74, -0.01, 0.0}), (PoseBin{1, -1, 18}));
  // Just either side of the +-pi seam: the first and the last yaw bin.
  EXPECT_EQ(binning.bin_of({0, 0, -pi + 1e-9}).yaw, 0);
  EXPECT_EQ(binning.bin_of({0, 0, pi - 1e-9}).yaw, 35);
  EXPECT_EQ(binning.bin_of({0, 0, pi}).yaw, 0);
}

TEST(PoseBinning, NeighboursWrapAroundTheCircle) {
  const PoseBinning binning(1.0, pi / 18);
  std::array<PoseBin, 26> around;
  ASSERT_EQ(binning.neighbours({0, 0, 0}, around), 26u);
  std::set<std::tuple<int, int, int>> distinct;
  for (const PoseBin& b : around) distinct.insert({b.x, b.y, b.yaw});
  EXPECT_EQ(distinct.size(), 26u);
  EXPECT_TRUE(distinct.count({0, 0, 35}));  // yaw bin 0's lower neighbour is the last
  EXPECT_FALSE(distinct.count({0, 0, 0}));

  const PoseBinning two_bins(1.0, pi);
  ASSERT_EQ(two_bins.yaw_bin_count(), 2);
  EXPECT_EQ(two_bins.neighbours({0, 0, 0}, around), 17u);  // 9 x 2 - itself
}

// Each touching pair of bins is one bin's forward neighbour: over a block
// of bins, the forward offsets seen from both ends give exactly the
// neighbour pairs, for every number of yaw bins (1 and 2 wrap onto
// themselves).
TEST(PoseBinning, ForwardNeighboursFindEveryTouchingPairOnce) {
  for (const double angle : {pi / 18, 2 * pi / 3, pi, 2 * pi}) {
    const PoseBinning binning(1.0, angle);
    const int yaw_bins = binning.yaw_bin_count();
    using Bin = std::tuple<int, int, int>;
    std::set<std::pair<Bin, Bin>> touching, found;
    std::size_t expected_forward = 0;
    for (int x = 0; x < 3; ++x) {
      for (int y = 0; y < 3; ++y) {
        for (int yaw = 0; yaw < yaw_bins; ++yaw) {
          const Bin from{x, y, yaw};
          std::array<PoseBin, 26> all;
          const std::size_t count = binning.neighbours({x, y, yaw}, all);
          for (std::size_t k = 0; k < count; ++k) {
            const Bin to{all[k].x, all[k].y, all[k].yaw};
            touching.insert({std::min(from, to), std::max(from, to)});
          }
          std::array<PoseBin, 13> forward;
          const std::size_t forward_count = binning.forward_neighbours({x, y, yaw}, forward);
          expected_forward = count == 26 ? 13 : (count == 17 ? 9 : 4);
          EXPECT_EQ(forward_count, expected_forward) << yaw_bins << " yaw bins";
          for (std::size_t k = 0; k < forward_count; ++k) {
            const Bin to{forward[k].x, forward[k].y, forward[k].yaw};
            const bool inserted = found.insert({std::min(from, to), std::max(from, to)}).second;
            EXPECT_TRUE(inserted || yaw_bins <= 2) << "a pair found twice, " << yaw_bins << " yaw bins";
          }
        }
      }
    }
    // Pairs reaching outside the block are found from inside only when
    // they point forward; compare within the block.
    const auto inside = [](const Bin& bin) {
      return std::get<0>(bin) >= 0 && std::get<0>(bin) < 3 && std::get<1>(bin) >= 0 && std::get<1>(bin) < 3;
    };
    std::set<std::pair<Bin, Bin>> touching_inside, found_inside;
    for (const auto& pair : touching) {
      if (inside(pair.first) && inside(pair.second)) touching_inside.insert(pair);
    }
    for (const auto& pair : found) {
      if (inside(pair.first) && inside(pair.second)) found_inside.insert(pair);
    }
    EXPECT_EQ(found_inside, touching_inside) << yaw_bins << " yaw bins";
    EXPECT_GE(touching_inside.size(), 20u);  // 3 x 3 cells, one yaw bin: 12 sides and 8 corners
  }
}

TEST(BinTable, AssignsDenseIndicesInInsertionOrderAndGrows) {
  BinTable table(4);
  for (std::uint64_t k = 0; k < 1000; ++k) {
    const auto [index, is_new] = table.insert(k * 7919);
    EXPECT_TRUE(is_new);
    EXPECT_EQ(index, k);
  }
  EXPECT_EQ(table.size(), 1000u);
  EXPECT_EQ(table.insert(7919 * 5).first, 5u);
  EXPECT_FALSE(table.insert(7919 * 5).second);
  EXPECT_EQ(table.find(7919 * 999), 999u);
  EXPECT_EQ(table.find(3), BinTable::not_found);
  table.clear();
  EXPECT_EQ(table.size(), 0u);
  for (std::uint64_t k = 0; k < 1000; ++k) ASSERT_EQ(table.find(k * 7919), BinTable::not_found) << k;
  EXPECT_EQ(table.insert(42).first, 0u);
}

// reset() empties the table whatever it was sized for before: a global
// search's hundred thousand bins, then a tracking filter's few hundred.
TEST(BinTable, ResetEmptiesAndResizesForTheNextUse) {
  BinTable table;
  table.reset(100000);
  for (std::uint64_t k = 0; k < 50000; ++k) ASSERT_TRUE(table.insert(k * 31).second);
  table.reset(100);  // shrinks
  EXPECT_EQ(table.size(), 0u);
  for (std::uint64_t k = 0; k < 50000; k += 7) ASSERT_EQ(table.find(k * 31), BinTable::not_found) << k;
  for (std::uint64_t k = 0; k < 300; ++k) {  // more than reset for: grows again
    const auto [index, is_new] = table.insert(k * 31 + 1);
    ASSERT_TRUE(is_new);
    ASSERT_EQ(index, k);
  }
  table.reset(100);  // keeps its size, empties the slots it used
  EXPECT_EQ(table.size(), 0u);
  for (std::uint64_t k = 0; k < 300; ++k) ASSERT_EQ(table.find(k * 31 + 1), BinTable::not_found) << k;
  EXPECT_EQ(table.insert(5).first, 0u);
  EXPECT_EQ(table.find(5), 0u);
}

TEST(PoseBinning, KeysOfDistinctNearbyBinsDiffer) {
  std::set<std::uint64_t> keys;
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int yaw = 0; yaw < 36; ++yaw) keys.insert(PoseBinning::key({x, y, yaw}));
  EXPECT_EQ(keys.size(), 7u * 7u * 36u);
}

TEST(DenseBinGrid, HoldsIndicesOverItsBoxAndVisitsThemInMemoryOrder) {
  DenseBinGrid grid;
  EXPECT_FALSE(grid.reset({0, 0, 0}, {9, 9, 0}, 36, 100 * 36 - 1));  // one bin too many
  ASSERT_TRUE(grid.reset({-2, 3, 0}, {1, 5, 0}, 4, 4 * 3 * 4));
  EXPECT_EQ(grid.find({-2, 3, 0}), BinTable::not_found);
  grid.at({1, 5, 3}) = 7;
  grid.at({-2, 3, 0}) = 2;
  grid.at({0, 4, 1}) = 5;
  EXPECT_EQ(grid.find({1, 5, 3}), 7u);
  EXPECT_EQ(grid.find({0, 4, 1}), 5u);
  EXPECT_EQ(grid.find({0, 4, 2}), BinTable::not_found);
  // Outside the box: not found, not read out of bounds.
  EXPECT_EQ(grid.find({2, 5, 3}), BinTable::not_found);
  EXPECT_EQ(grid.find({-3, 4, 0}), BinTable::not_found);
  EXPECT_EQ(grid.find({0, 6, 0}), BinTable::not_found);
  EXPECT_EQ(grid.find({0, 2, 0}), BinTable::not_found);
  std::vector<std::tuple<int, int, int, std::uint32_t>> seen;
  grid.for_each([&](const PoseBin& bin, std::uint32_t index) { seen.emplace_back(bin.x, bin.y, bin.yaw, index); });
  EXPECT_EQ(seen, (std::vector<std::tuple<int, int, int, std::uint32_t>>{{-2, 3, 0, 2}, {0, 4, 1, 5}, {1, 5, 3, 7}}));
  // A reset empties it.
  ASSERT_TRUE(grid.reset({-2, 3, 0}, {1, 5, 0}, 4, 1000));
  EXPECT_EQ(grid.find({1, 5, 3}), BinTable::not_found);
}

}  // namespace pose_bins_test
}  // namespace playerkit::amcl
