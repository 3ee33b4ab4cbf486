#include "sim/world/blobfinder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "sim/world/sensor_test_support.hpp"

namespace playerkit::sim::blobfinder_test {

using namespace sensor_test_support;
using geometry::Pose2;
constexpr double kPi = std::numbers::pi;

constexpr Rgb kRed{255, 0, 0};
constexpr Rgb kGreen{0, 255, 0};
constexpr Rgb kBlue{0, 0, 255};
constexpr Rgb kYellow{255, 255, 0};

constexpr double kFov = kPi / 3.0;
constexpr int kWidth = 80;
constexpr int kHeight = 60;
constexpr double kColumnStep = kFov / (kWidth - 1);

// The camera at the origin looking along +x, on a red robot. In view, left
// to right: a small red box, a red box, a wall hiding a blue box, a green
// disc, a yellow box hiding a red one.
struct Room {
  Scene scene;
  ModelId robot = kNoModel, far_red = kNoModel, red = kNoModel, blue = kNoModel, green = kNoModel,
          yellow = kNoModel, hidden_red = kNoModel;

  explicit Room(bool with_wall = true) : scene(make_map(with_wall)) {
    robot = add_model(scene, {}, disc(0.4), {}, kRed);
    far_red = add_model(scene, {4.0, 1.9, 0.0}, box(0.3, 0.3), {}, kRed);
    red = add_model(scene, {3.0, 0.8, 0.0}, box(0.4, 0.4), {}, kRed);
    blue = add_model(scene, {3.5, 0.0, 0.0}, box(0.3, 0.3), {}, kBlue);
    green = add_model(scene, {4.0, -1.0, 0.0}, disc(0.6), {}, kGreen);
    yellow = add_model(scene, {2.5, -1.2, 0.0}, box(0.3, 0.3), {}, kYellow);
    hidden_red = add_model(scene, {4.0, -1.9, 0.0}, box(0.2, 0.2), {}, kRed);
  }

  static grid::OccupancyGrid make_map(bool with_wall) {
    grid::OccupancyGrid map = room();
    if (with_wall) add_wall(map, 2.0, -0.3, 2.2, 0.2);
    return map;
  }
};

const BlobfinderSpec kSpec{.channels = {}, .image_width = kWidth, .image_height = kHeight, .range = 12.0, .fov = kFov};

const BlobfinderSpec kOneColumn{.channels = {}, .image_width = 1, .image_height = kHeight};

// The columns whose rays fall within [min_bearing, max_bearing]; column c
// looks along fov/2 - c * step (the image's left is the fov's left).
std::pair<int, int> columns_between(double min_bearing, double max_bearing) {
  return {static_cast<int>(std::ceil((kFov / 2.0 - max_bearing) / kColumnStep)),
          static_cast<int>(std::floor((kFov / 2.0 - min_bearing) / kColumnStep))};
}

// A box's bearings, seen from the origin: those of its extreme corners.
std::pair<int, int> box_columns(double x, double y, double size) {
  double low = kPi, high = -kPi;
  for (const double dx : {-size / 2.0, size / 2.0}) {
    for (const double dy : {-size / 2.0, size / 2.0}) {
      low = std::min(low, std::atan2(y + dy, x + dx));
      high = std::max(high, std::atan2(y + dy, x + dx));
    }
  }
  return columns_between(low, high);
}

std::pair<int, int> disc_columns(double x, double y, double diameter) {
  const double half = std::asin(diameter / 2.0 / std::hypot(x, y));
  return columns_between(std::atan2(y, x) - half, std::atan2(y, x) + half);
}

// The blob a run over these columns makes, its range from a march of each
// column's ray and its height from the 0.6 m object rule.
Blob expected_blob(const Room& room, int channel, Rgb color, std::pair<int, int> columns) {
  Blob blob;
  blob.channel = channel;
  blob.color = color;
  blob.left = columns.first;
  blob.right = columns.second;
  double sum = 0.0;
  for (int c = blob.left; c <= blob.right; ++c) {
    sum += march(room.scene, {0.0, 0.0}, kFov / 2.0 - c * kColumnStep, 12.0, room.robot, any_body_stops).range;
  }
  blob.range = sum / (blob.right - blob.left + 1);
  // Square pixels: a row spans fov / width radians.
  const int half_rows = static_cast<int>(std::atan2(0.3, blob.range) / (kFov / kWidth));
  blob.top = std::max(kHeight / 2 - half_rows, 0);
  blob.bottom = std::min(kHeight / 2 + half_rows, kHeight - 1);
  blob.x = (blob.left + blob.right) / 2;
  blob.y = (blob.top + blob.bottom) / 2;
  blob.area = (blob.right - blob.left + 1) * (blob.bottom - blob.top + 1);
  return blob;
}

void expect_blobs(const BlobScan& scan, const std::vector<Blob>& expected) {
  EXPECT_EQ(scan.image_width, kWidth);
  EXPECT_EQ(scan.image_height, kHeight);
  ASSERT_EQ(scan.blobs.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    const Blob& got = scan.blobs[i];
    const Blob& want = expected[i];
    EXPECT_EQ(got.channel, want.channel);
    EXPECT_EQ(got.color.packed(), want.color.packed());
    EXPECT_EQ(got.left, want.left);
    EXPECT_EQ(got.right, want.right);
    EXPECT_EQ(got.top, want.top);
    EXPECT_EQ(got.bottom, want.bottom);
    EXPECT_EQ(got.x, want.x);
    EXPECT_EQ(got.y, want.y);
    EXPECT_EQ(got.area, want.area);
    EXPECT_NEAR(got.range, want.range, kMarchStep + 1e-9);
  }
}

TEST(Blobfinder, WithoutChannelsEveryColourIsOneInTheOrderFirstSeen) {
  const Room room;
  const BlobScan scan = find_blobs(room.scene, kSpec, {}, kFov, room.robot);
  expect_blobs(scan, {expected_blob(room, 0, kRed, box_columns(4.0, 1.9, 0.3)),
                      expected_blob(room, 0, kRed, box_columns(3.0, 0.8, 0.4)),
                      expected_blob(room, 1, kGreen, disc_columns(4.0, -1.0, 0.6)),
                      expected_blob(room, 2, kYellow, box_columns(2.5, -1.2, 0.3))});
  // The geometry, worked out by hand for the red box: its corners (2.8, 1.0)
  // and (3.2, 0.6) lie at 0.343 and 0.185 rad, columns 13.6 and 25.5.
  EXPECT_EQ(scan.blobs[1].left, 14);
  EXPECT_EQ(scan.blobs[1].right, 25);
  EXPECT_EQ(scan.time, 0.0);
}

TEST(Blobfinder, ListedChannelsKeepTheirOrderAndOtherColoursAreNoBlobs) {
  const Room room;
  BlobfinderSpec spec = kSpec;
  spec.channels = {kGreen, kBlue, kRed};
  const BlobScan scan = find_blobs(room.scene, spec, {}, kFov, room.robot);
  expect_blobs(scan, {expected_blob(room, 0, kGreen, disc_columns(4.0, -1.0, 0.6)),
                      expected_blob(room, 2, kRed, box_columns(4.0, 1.9, 0.3)),
                      expected_blob(room, 2, kRed, box_columns(3.0, 0.8, 0.4))});
}

TEST(Blobfinder, NothingIsSeenBehindAWallOrAnotherBody) {
  const Room walled;
  const Room open(false);
  const auto colours = [](const BlobScan& scan) {
    std::vector<std::uint32_t> seen;
    for (const Blob& blob : scan.blobs) seen.push_back(blob.color.packed());
    return seen;
  };
  const std::vector<std::uint32_t> behind_wall = colours(find_blobs(walled.scene, kSpec, {}, kFov, walled.robot));
  const std::vector<std::uint32_t> in_the_open = colours(find_blobs(open.scene, kSpec, {}, kFov, open.robot));
  EXPECT_EQ(std::count(behind_wall.begin(), behind_wall.end(), kBlue.packed()), 0);
  EXPECT_EQ(std::count(in_the_open.begin(), in_the_open.end(), kBlue.packed()), 1);
  // The red box behind the yellow one never shows: red blobs are the two in view.
  EXPECT_EQ(std::count(in_the_open.begin(), in_the_open.end(), kRed.packed()), 2);

  // Looking straight at the hidden red box, the camera meets the yellow one
  // in front of it; from beside the red box, it sees it.
  const double towards_hidden = std::atan2(-1.9, 4.0);
  const BlobScan turned = find_blobs(open.scene, kOneColumn, {0.0, 0.0, towards_hidden},
                                     kFov, open.robot);
  ASSERT_EQ(turned.blobs.size(), 1u);
  EXPECT_EQ(turned.blobs[0].color, kYellow);
  const BlobScan from_beside = find_blobs(open.scene, kOneColumn,
                                          {3.5, -1.9, 0.0}, kFov, open.robot);
  ASSERT_EQ(from_beside.blobs.size(), 1u);
  EXPECT_EQ(from_beside.blobs[0].color, kRed);
  EXPECT_NEAR(from_beside.blobs[0].range, 0.4, 1e-9);
}

TEST(Blobfinder, OneColumnLooksStraightAheadAndTheImageLeftIsTheFovLeft) {
  const Room room;
  // Turned so the green disc's centre is straight ahead.
  const double towards_green = std::atan2(-1.0, 4.0);
  const BlobScan ahead = find_blobs(room.scene, kOneColumn,
                                    {0.0, 0.0, towards_green}, kFov, room.robot);
  ASSERT_EQ(ahead.blobs.size(), 1u);
  EXPECT_EQ(ahead.blobs[0].color, kGreen);
  EXPECT_NEAR(ahead.blobs[0].range, std::hypot(4.0, 1.0) - 0.3, 1e-9);
  EXPECT_EQ(ahead.blobs[0].left, 0);
  EXPECT_EQ(ahead.blobs[0].right, 0);

  // Turned right by a quarter of the fov, the red box moves to the image's
  // left edge, partly out of view.
  const BlobScan turned = find_blobs(room.scene, kSpec, {0.0, 0.0, -kFov / 4.0}, kFov, room.robot);
  ASSERT_FALSE(turned.blobs.empty());
  const Blob& red = turned.blobs[0];
  EXPECT_EQ(red.color, kRed);
  double low = kPi, high = -kPi;
  for (const double x : {2.8, 3.2}) {
    for (const double y : {0.6, 1.0}) {
      low = std::min(low, std::atan2(y, x) + kFov / 4.0);
      high = std::max(high, std::atan2(y, x) + kFov / 4.0);
    }
  }
  const auto [left, right] = columns_between(low, high);
  EXPECT_EQ(red.left, std::max(left, 0));
  EXPECT_EQ(red.right, right);
}

TEST(Blobfinder, ANearBlobIsClampedToTheImageHeight) {
  Scene scene(room());
  const ModelId robot = add_model(scene, {}, disc(0.2));
  add_model(scene, {0.35, 0.0, 0.0}, box(0.1, 2.0), {}, kBlue);
  const BlobScan scan = find_blobs(scene, kSpec, {}, kFov, robot);
  ASSERT_EQ(scan.blobs.size(), 1u);
  // At 0.3 m the 0.6 m object spans 90°, more than the 45° vertical fov.
  EXPECT_EQ(scan.blobs[0].top, 0);
  EXPECT_EQ(scan.blobs[0].bottom, kHeight - 1);
  EXPECT_EQ(scan.blobs[0].left, 0);
  EXPECT_EQ(scan.blobs[0].right, kWidth - 1);
  EXPECT_EQ(scan.blobs[0].area, kWidth * kHeight);
}

TEST(Blobfinder, ModelsWithoutABlobReturnHideButShowNothing) {
  Scene scene(room());
  const ModelId robot = add_model(scene, {}, disc(0.2));
  add_model(scene, {2.0, 0.0, 0.0}, box(0.2, 0.6), {.blob = false}, kRed);
  add_model(scene, {3.0, 0.0, 0.0}, box(0.2, 0.6), {}, kGreen);
  EXPECT_TRUE(find_blobs(scene, kSpec, {}, kFov, robot).blobs.empty());
}

TEST(Blobfinder, BodiesRangersSeeThroughStillHideWhatIsBehindThem) {
  Scene scene(room());
  const ModelId robot = add_model(scene, {}, disc(0.2));
  add_model(scene, {2.0, 0.0, 0.0}, box(0.2, 0.6), {.obstacle = false, .ranger = -1.0}, kGreen);
  add_model(scene, {3.0, 0.0, 0.0}, box(0.2, 0.6), {}, kRed);
  const BlobScan scan = find_blobs(scene, kSpec, {}, kFov, robot);
  ASSERT_EQ(scan.blobs.size(), 1u);
  EXPECT_EQ(scan.blobs[0].color, kGreen);
}

}  // namespace playerkit::sim::blobfinder_test
