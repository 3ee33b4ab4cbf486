#include "algorithms/amcl/pose_bins.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <set>
#include <tuple>

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
  EXPECT_EQ(table.find(7919 * 5), BinTable::not_found);
}

TEST(PoseBinning, KeysOfDistinctNearbyBinsDiffer) {
  std::set<std::uint64_t> keys;
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int yaw = 0; yaw < 36; ++yaw) keys.insert(PoseBinning::key({x, y, yaw}));
  EXPECT_EQ(keys.size(), 7u * 7u * 36u);
}

}  // namespace pose_bins_test
}  // namespace playerkit::amcl
