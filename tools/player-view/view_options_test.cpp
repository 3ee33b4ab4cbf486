#include "view_options.hpp"

#include <gtest/gtest.h>

#include "protocol/interfaces.hpp"

namespace playerkit::player_view {
namespace view_options_test {

CommandLine snapshot_of(std::vector<std::string> targets) {
  CommandLine command_line;
  command_line.targets = std::move(targets);
  command_line.snapshot = "out.png";
  return command_line;
}

std::string usage_error(const CommandLine& command_line) {
  try {
    (void)make_view_options(command_line);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no UsageError";
}

TEST(ViewOptions, ASnapshotOfEveryDeviceByDefault) {
  const auto options = make_view_options(snapshot_of({}));
  EXPECT_EQ(options.server, client::ServerEndpoint{});
  EXPECT_TRUE(options.devices.empty());
  EXPECT_EQ(options.output, Output::kSnapshot);
  EXPECT_EQ(options.snapshot, "out.png");
  EXPECT_DOUBLE_EQ(options.after, kDefaultAfter);
  EXPECT_EQ(options.render.width, 800);
  EXPECT_EQ(options.render.height, 800);
  EXPECT_FALSE(options.map);
}

TEST(ViewOptions, ServerDevicesSizeAndMap) {
  auto command_line = snapshot_of({"robot:7000", "laser:0", "position"});
  command_line.size = "640x480";
  command_line.after = 2.5;
  command_line.map = "cave.pnm";
  command_line.scale = 0.03;
  command_line.negate = true;
  command_line.origin = "0,-1.5";
  const auto options = make_view_options(command_line);
  EXPECT_EQ(options.server.host, "robot");
  EXPECT_EQ(options.server.port, 7000);
  ASSERT_EQ(options.devices.size(), 2u);
  EXPECT_EQ(options.devices[1], (protocol::DeviceAddress{protocol::kPositionCode, 0}));
  EXPECT_EQ(options.render.width, 640);
  EXPECT_EQ(options.render.height, 480);
  EXPECT_DOUBLE_EQ(options.after, 2.5);
  ASSERT_TRUE(options.map);
  EXPECT_EQ(*options.map_loading.resolution, 0.03);
  EXPECT_TRUE(options.map_loading.negate);
  EXPECT_EQ(*options.map_loading.origin, Eigen::Vector2d(0.0, -1.5));
}

TEST(ViewOptions, Record) {
  CommandLine command_line;
  command_line.record = "frames";
  command_line.every = 0.5;
  command_line.count = 3;
  const auto options = make_view_options(command_line);
  EXPECT_EQ(options.output, Output::kRecord);
  EXPECT_EQ(options.record_dir, "frames");
  EXPECT_DOUBLE_EQ(options.every, 0.5);
  EXPECT_EQ(options.count, 3u);
  EXPECT_EQ(record_file_name(1), "frame-000001.png");
}

TEST(ViewOptions, TheLivePageListensOnLoopbackByDefault) {
  CommandLine command_line;
  command_line.http = 8080;
  auto options = make_view_options(command_line);
  EXPECT_EQ(options.output, Output::kHttp);
  EXPECT_EQ(options.http_port, 8080);
  EXPECT_EQ(options.bind, "127.0.0.1");
  command_line.bind = "0.0.0.0";
  EXPECT_EQ(make_view_options(command_line).bind, "0.0.0.0");
  EXPECT_FALSE(make_view_options(command_line).drive);
  command_line.drive = true;
  command_line.turn = 90;
  const auto driving = make_view_options(command_line);
  EXPECT_TRUE(driving.drive);
  EXPECT_DOUBLE_EQ(driving.speed, 0.3);
  EXPECT_NEAR(driving.turn_rate, 1.5707963, 1e-6);
  command_line.speed = 0;
  EXPECT_EQ(usage_error(command_line), "--speed must be more than 0 and at most 10 m/s");
  command_line.speed = 0.3;
  command_line.after = 1.0;
  EXPECT_EQ(usage_error(command_line), "--after applies to --snapshot, not to the live page");
  auto snapshot = snapshot_of({});
  snapshot.drive = true;
  EXPECT_EQ(usage_error(snapshot), "--drive lets the live page drive the robot: it needs --http");
}

TEST(ViewOptions, ErrorsNameTheFlag) {
  EXPECT_EQ(usage_error(CommandLine{}),
            "say what to make: --http PORT (a live page), --snapshot FILE.png or --record DIR --every SECONDS");
  auto both = snapshot_of({});
  both.record = "dir";
  EXPECT_EQ(usage_error(both), "--snapshot, --record and --http: choose one");
  auto bind = snapshot_of({});
  bind.bind = "0.0.0.0";
  EXPECT_EQ(usage_error(bind), "--bind sets the live page's address: it needs --http");
  CommandLine record;
  record.record = "dir";
  EXPECT_EQ(usage_error(record), "--record needs --every SECONDS between pictures");
  auto every = snapshot_of({});
  every.every = 1.0;
  EXPECT_NE(usage_error(every).find("--every"), std::string::npos);
  auto size = snapshot_of({});
  size.size = "800";
  EXPECT_NE(usage_error(size).find("--size '800'"), std::string::npos);
  size.size = "8x800";
  EXPECT_NE(usage_error(size).find("16 to 8192"), std::string::npos);
  auto scale = snapshot_of({});
  scale.scale = 0.05;
  EXPECT_EQ(usage_error(scale), "--scale is the map image's metres per pixel: it needs --map");
  auto origin = snapshot_of({});
  origin.map = "m.pgm";
  origin.origin = "1;2";
  EXPECT_EQ(usage_error(origin), "--origin: '1;2' is not X,Y (two numbers in metres)");
  origin.origin = "1,2x";
  EXPECT_EQ(usage_error(origin), "--origin: '1,2x' is not X,Y (two numbers in metres)");
  auto after = snapshot_of({});
  after.after = -1;
  EXPECT_EQ(usage_error(after), "--after must be a non-negative number of seconds");
  EXPECT_NE(usage_error(snapshot_of({"laser:0", "bogus"})).find("'bogus' is not a device"), std::string::npos);
  EXPECT_EQ(usage_error(snapshot_of({"laser", "laser:0"})), "device laser:0 is named twice");
  auto span = snapshot_of({});
  span.span = 0;
  EXPECT_EQ(usage_error(span), "--span must be a positive number of metres");
}

}  // namespace view_options_test
}  // namespace playerkit::player_view
