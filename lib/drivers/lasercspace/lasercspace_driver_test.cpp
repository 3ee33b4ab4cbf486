// lasercspace on a laser of the test's own: the sheet's scan in, its
// table out (lasercspace.md §6), the timestamp kept, a repeated scan not
// recomputed, range_res honoured, GET_GEOM answered with the source's
// geometry, and the configurations 1.5 refused refused with their place.

#include "drivers/lasercspace/lasercspace_driver.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "config/errors.hpp"
#include "core/device.hpp"
#include "core/driver.hpp"
#include "drivers/test_support.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::drivers {
namespace lasercspace_driver_test {

using namespace std::chrono_literals;
using testing::eventually;

const protocol::LaserGeom kSourceGeometry{.subtype = 1, .pose = {{160, -20, 0}}, .size = {{155, 185}}};

// A laser that answers GET_GEOM from its own thread; the test publishes its scans.
class SourceLaser final : public core::ThreadedDriver {
 public:
  core::RequestResult handle_request(const core::Request& request) override {
    if (request.subtype() == protocol::kLaserGetGeom) return core::RequestResult::ack(protocol::encode(kSourceGeometry));
    return core::RequestResult::nack();
  }

 protected:
  void run(std::stop_token stop) override {
    while (sleep_for(stop, 1ms)) device().service_requests();
  }
};

struct LaserCspace : ::testing::Test {
  LaserCspace() {
    devices.registry.add({.name = "sourcelaser",
                          .interfaces = {protocol::kLaserCode},
                          .access = protocol::Access::kRead,
                          .factory = [](const core::DriverContext&) -> std::unique_ptr<core::Driver> {
                            return std::make_unique<SourceLaser>();
                          },
                          .limits = {},
                          .summary = "test"});
  }
  void load(const std::string& cspace_options = "") {
    devices.load("laser:0 ( driver \"sourcelaser\" )\n"
                 "laser:1 ( driver \"lasercspace\" " + cspace_options + ")\n");
    ASSERT_TRUE(cspace().subscribe());
  }
  core::Device& source() { return devices.device(protocol::kLaserCode, 0); }
  core::Device& cspace() { return devices.device(protocol::kLaserCode, 1); }

  // Publishes `scan` on the source and returns what lasercspace made of it.
  std::optional<protocol::LaserData> convert(const protocol::LaserData& scan, protocol::Timestamp time) {
    const std::uint64_t before = cspace().latest_data()->sequence;
    source().publish(protocol::encode(scan), time);
    if (!eventually([&] { return cspace().latest_data()->sequence > before; }, 5s)) return std::nullopt;
    return protocol::decode<protocol::LaserData>(cspace().latest_data()->payload);
  }

  std::optional<core::Reply> ask(std::vector<std::uint8_t> payload) {
    (void)cspace().take_replies();
    EXPECT_EQ(cspace().enqueue_request({1, cspace().address(), std::move(payload), {}}),
              core::Device::RequestStatus::kQueued);
    std::optional<core::Reply> reply;
    eventually([&] {
      auto replies = cspace().take_replies();
      if (!replies.empty()) reply = replies.front();
      return reply.has_value();
    }, 5s);
    return reply;
  }

  testing::BuiltinDevices devices;
};

// The sheet's scan: 181 beams from -90 degrees, one a degree, all 8 m but
// the one straight ahead at 2 m, in `range_res` units.
protocol::LaserData one_post_ahead(std::uint16_t range_res = 1) {
  protocol::LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 100;
  scan.range_res = range_res;
  scan.range_count = 181;
  for (std::size_t i = 0; i < 181; ++i) {
    scan.ranges[i] = static_cast<std::uint16_t>((i == 90 ? 2000 : 8000) / range_res);
    scan.intensity[i] = 3;
  }
  return scan;
}

TEST_F(LaserCspace, ShortensTheSheetsScanAsItsTableSays) {
  load();
  const protocol::Timestamp taken{1000, 250000};
  const auto out = convert(one_post_ahead(), taken);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->min_angle, -9000);
  EXPECT_EQ(out->max_angle, 9000);
  EXPECT_EQ(out->resolution, 100);
  EXPECT_EQ(out->range_count, 181);
  EXPECT_EQ(out->range_res, 1);  // 1.5 sent 0 (lasercspace.md §5)
  const int table[] = {1500, 1500, 1503, 1508, 1514, 1523, 1534, 1548, 1565, 1585, 1609, 1640, 1678, 1730, 1814};
  for (int bearing = 0; bearing < 15; ++bearing) {
    EXPECT_EQ(out->ranges[90 + bearing], table[bearing]) << bearing;
    EXPECT_EQ(out->ranges[90 - bearing], table[bearing]) << -bearing;
  }
  EXPECT_EQ(out->ranges[0], 7500);
  EXPECT_EQ(out->ranges[180], 7500);
  for (std::size_t i = 0; i < 181; ++i) EXPECT_EQ(out->intensity[i], 0) << i;
  EXPECT_EQ(cspace().latest_data()->timestamp, taken);
}

std::uint64_t counter(const core::Device& device, const std::string& name) {
  for (const core::DriverCounter& c : device.driver().counters()) {
    if (c.name == name) return c.value;
  }
  return ~std::uint64_t{0};
}

TEST_F(LaserCspace, AScanWithTheSameTimestampIsNotComputedAgain) {
  load();
  ASSERT_TRUE(convert(one_post_ahead(), {1000, 0}));
  const std::uint64_t after_first = cspace().latest_data()->sequence;
  source().publish(protocol::encode(one_post_ahead()), {1000, 0});
  ASSERT_TRUE(eventually([&] { return counter(cspace(), "scans_repeated") == 1; }, 5s));
  EXPECT_EQ(cspace().latest_data()->sequence, after_first);
  ASSERT_TRUE(convert(one_post_ahead(), {1000, 100000}));
  EXPECT_EQ(counter(cspace(), "scans_converted"), 2u);
}

TEST_F(LaserCspace, ReadsRangesInTheSourcesRangeRes) {
  load("radius 0.5");
  const auto out = convert(one_post_ahead(10), {1, 0});
  ASSERT_TRUE(out);
  EXPECT_EQ(out->ranges[90], 1500);
  EXPECT_EQ(out->ranges[0], 7500);
}

TEST_F(LaserCspace, TheRadiusAndStepOptionsChangeTheResult) {
  load("radius 0.25 step 2");
  const auto out = convert(one_post_ahead(), {1, 0});
  ASSERT_TRUE(out);
  EXPECT_EQ(out->ranges[90], 1750);
  EXPECT_EQ(out->ranges[100], 7750);  // 2 sin(10 degrees) > 0.25: the post is not in the way
}

TEST_F(LaserCspace, AnswersGetGeomWithTheSourcesGeometryAndRefusesTheRest) {
  load();
  const auto geometry = ask(protocol::encode(protocol::LaserGeom{.subtype = 1, .pose = {}, .size = {}}));
  ASSERT_TRUE(geometry);
  ASSERT_EQ(geometry->type, protocol::MessageType::kAck);
  EXPECT_EQ(protocol::decode<protocol::LaserGeom>(geometry->payload), kSourceGeometry);
  const auto other = ask({2, 0});
  ASSERT_TRUE(other);
  EXPECT_EQ(other->type, protocol::MessageType::kNack);
  EXPECT_TRUE(source().take_replies().empty());  // the source's answer went to lasercspace only
}

// The server checks every device before it serves any (player-serve --check).
std::string check_error(core::Device& device) {
  try {
    device.check();
  } catch (const core::DriverError& e) {
    return e.what();
  }
  return "";
}

TEST_F(LaserCspace, RefusesToReadItselfOrALaserThatIsNotThere) {
  devices.load("laser:0 ( driver \"lasercspace\" )\n"
               "laser:1 ( driver \"lasercspace\" laser 2 )\n");
  core::Device& itself = devices.device(protocol::kLaserCode, 0);
  EXPECT_NE(check_error(itself).find("laser 0 is this device itself"), std::string::npos) << check_error(itself);
  EXPECT_FALSE(itself.subscribe());
  core::Device& orphan = devices.device(protocol::kLaserCode, 1);
  EXPECT_NE(check_error(orphan).find("no laser:2 on port 6665"), std::string::npos) << check_error(orphan);
  EXPECT_FALSE(orphan.subscribe());
}

TEST_F(LaserCspace, ABadOptionIsRefusedAtItsPlace) {
  try {
    devices.load("laser:1 ( driver \"lasercspace\" laser 0 radius -0.5 )\n");
    FAIL() << "a negative radius was accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("test.cfg:1:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos) << e.what();
  }
}

}  // namespace lasercspace_driver_test
}  // namespace playerkit::drivers
