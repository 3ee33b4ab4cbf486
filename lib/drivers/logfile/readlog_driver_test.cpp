#include "drivers/logfile/readlog_driver.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "config/errors.hpp"
#include "drivers/logfile/logfile_test_support.hpp"
#include "drivers/test_support.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {
namespace readlog_driver_test {

using namespace std::chrono_literals;
using protocol::kPositionCode;
using protocol::Timestamp;
using testing::eventually;
using testing::LoggedSample;
using testing::position_payload;

// position:0 at 0, 0.5 and 1.0 s; position:1 at 0.25 s (logged times from 1000 s).
const std::vector<LoggedSample> kFourLines{
    {0, {1000, 0}, 100}, {1, {1000, 250000}, 150}, {0, {1000, 500000}, 200}, {0, {1001, 0}, 300}};

struct ReadlogTest : ::testing::Test {
  // Registers readlog as `player-serve -r LOG -f speed` would, with a timer
  // the test moves, then loads `config`.
  void load(const std::string& config, const std::vector<LoggedSample>& samples = kFourLines,
            double speed = 1.0, ReadlogSettings settings = {}) {
    testing::write_position_log(log_path, samples);
    settings.log = log_path;
    settings.speed = speed;
    settings.timer = timer;
    builtin.registry.add(readlog_driver_spec(std::move(settings)));
    builtin.load(config);
  }

  core::Device& position(std::uint16_t index) { return builtin.device(kPositionCode, index); }

  bool waiting_for(std::chrono::nanoseconds deadline) {
    return eventually([&] { return timer->waiting_for() == deadline; });
  }
  bool has_sequence(core::Device& device, std::uint64_t sequence) {
    return eventually([&] { return device.latest_data()->sequence == sequence; });
  }

  testing::ScratchDirectory scratch;
  std::filesystem::path log_path = scratch.file("run.log");
  std::shared_ptr<testing::ManualReplayTimer> timer = std::make_shared<testing::ManualReplayTimer>();
  testing::BuiltinDevices builtin;  // last: its devices stop before the timer and clock go
};

TEST_F(ReadlogTest, PublishesAtTheLoggedPaceWithTheLoggedTimestamps) {
  load("position:0 ( driver \"readlog\" )\nposition:1 ( driver \"readlog\" )\n");
  // Before anyone subscribes the clock already reads the log's first time.
  EXPECT_EQ(builtin.clock.now(), (Timestamp{1000, 0}));
  core::Device& device = position(0);
  ASSERT_TRUE(device.subscribe());

  ASSERT_TRUE(has_sequence(device, 1));
  EXPECT_EQ(device.latest_data()->payload, position_payload(100));
  EXPECT_EQ(device.latest_data()->timestamp, (Timestamp{999, 900000}));  // the logged data time
  EXPECT_EQ(builtin.clock.now(), (Timestamp{1000, 0}));

  // The position:1 line (0.25 s later) waits its turn; nothing else goes early.
  ASSERT_TRUE(waiting_for(250ms));
  EXPECT_EQ(device.latest_data()->sequence, 1u);
  timer->set(250ms);
  ASSERT_TRUE(waiting_for(500ms));
  EXPECT_EQ(builtin.clock.now(), (Timestamp{1000, 250000}));
  EXPECT_EQ(device.latest_data()->sequence, 1u);          // not its index
  EXPECT_EQ(position(1).latest_data()->sequence, 0u);     // not subscribed

  timer->set(500ms);
  ASSERT_TRUE(has_sequence(device, 2));
  EXPECT_EQ(device.latest_data()->payload, position_payload(200));
  EXPECT_EQ(device.latest_data()->timestamp, (Timestamp{1000, 400000}));
  ASSERT_TRUE(waiting_for(1000ms));
  timer->set(1000ms);
  ASSERT_TRUE(has_sequence(device, 3));
  EXPECT_EQ(device.latest_data()->payload, position_payload(300));
  EXPECT_EQ(builtin.clock.now(), (Timestamp{1001, 0}));

  // After the last line the server clock keeps running from the log's end.
  ASSERT_TRUE(waiting_for(1100ms));
  timer->set(1100ms);
  ASSERT_TRUE(eventually([&] { return builtin.clock.now() == Timestamp{1001, 100000}; }));
  EXPECT_EQ(device.latest_data()->sequence, 3u);  // no rewind
  device.unsubscribe();
}

TEST_F(ReadlogTest, SpeedDividesTheWaits) {
  load("position:0 ( driver \"readlog\" )\n", kFourLines, 2.0);
  ASSERT_TRUE(position(0).subscribe());
  ASSERT_TRUE(has_sequence(position(0), 1));
  ASSERT_TRUE(waiting_for(125ms));
  timer->set(125ms);
  ASSERT_TRUE(waiting_for(250ms));
  timer->set(250ms);
  ASSERT_TRUE(has_sequence(position(0), 2));
  ASSERT_TRUE(waiting_for(500ms));
  // After the end the clock runs at the replay speed too: 0.1 s real = 0.2 s log.
  timer->set(500ms);
  ASSERT_TRUE(has_sequence(position(0), 3));
  ASSERT_TRUE(waiting_for(600ms));
  timer->set(600ms);
  ASSERT_TRUE(eventually([&] { return builtin.clock.now() == Timestamp{1001, 200000}; }));
}

TEST_F(ReadlogTest, SpeedOptionOverridesTheCommandLine) {
  load("position:0 ( driver \"readlog\" speed 0.5 )\n", kFourLines, 2.0);
  ASSERT_TRUE(position(0).subscribe());
  ASSERT_TRUE(has_sequence(position(0), 1));
  ASSERT_TRUE(waiting_for(500ms));  // 0.25 s of log at half speed
}

TEST_F(ReadlogTest, StartOffsetSkipsTheBeginning) {
  load("position:0 ( driver \"readlog\" start 0.4 )\n");
  ASSERT_TRUE(position(0).subscribe());
  ASSERT_TRUE(has_sequence(position(0), 1));
  EXPECT_EQ(position(0).latest_data()->payload, position_payload(200));  // the line at 0.5 s
  EXPECT_EQ(builtin.clock.now(), (Timestamp{1000, 500000}));
  ASSERT_TRUE(waiting_for(500ms));  // the next line, 0.5 s of log later
}

TEST_F(ReadlogTest, AutorewindStartsAgainFromTheTop) {
  load("position:0 ( driver \"readlog\" autorewind 1 )\n",
       {{0, {1000, 0}, 100}, {0, {1000, 500000}, 200}});
  core::Device& device = position(0);
  ASSERT_TRUE(device.subscribe());
  ASSERT_TRUE(has_sequence(device, 1));
  ASSERT_TRUE(waiting_for(500ms));
  timer->set(500ms);
  // Second pass: the first line again at once, with its logged time and timestamp.
  ASSERT_TRUE(has_sequence(device, 3));
  EXPECT_EQ(device.latest_data()->payload, position_payload(100));
  EXPECT_EQ(device.latest_data()->timestamp, (Timestamp{999, 900000}));
  EXPECT_EQ(builtin.clock.now(), (Timestamp{1000, 0}));
  ASSERT_TRUE(waiting_for(1000ms));
}

TEST_F(ReadlogTest, IndexOptionPicksTheLoggedDevice) {
  load("position:0 ( driver \"readlog\" )\nposition:3 ( driver \"readlog\" index 1 )\n");
  // position:0 first: the shared reader delivers the log's first line as it
  // starts, and a device not yet subscribed would miss it.
  ASSERT_TRUE(position(0).subscribe());
  ASSERT_TRUE(position(3).subscribe());
  // Both share one reader: the first line has gone to position:0 ...
  ASSERT_TRUE(has_sequence(position(0), 1));
  timer->set(250ms);
  // ... and position:1's line to position:3.
  ASSERT_TRUE(has_sequence(position(3), 1));
  EXPECT_EQ(position(3).latest_data()->payload, position_payload(150));
  EXPECT_EQ(position(0).latest_data()->sequence, 1u);
}

TEST_F(ReadlogTest, EveryRequestGetsNackAtOnce) {
  load("position:0 ( driver \"readlog\" )\n");
  core::Device& device = position(0);
  ASSERT_TRUE(device.subscribe());
  for (const int subtype : {1, 2, 3, 6}) {
    ASSERT_EQ(device.enqueue_request(
                  testing::make_request(kPositionCode, {static_cast<std::uint8_t>(subtype)})),
              core::Device::RequestStatus::kQueued);
  }
  device.update();  // one server round
  const auto replies = device.take_replies();
  ASSERT_EQ(replies.size(), 4u);
  for (const core::Reply& reply : replies) EXPECT_EQ(reply.type, protocol::MessageType::kNack);
  EXPECT_EQ(builtin.registry.find("readlog")->access, protocol::Access::kRead);
}

TEST_F(ReadlogTest, FilenameOptionWorksWithoutMinusR) {
  testing::write_position_log(log_path, kFourLines);
  builtin.load("position:0 ( driver \"readlog\" filename \"" + log_path.string() + "\" )\n");
  ASSERT_TRUE(position(0).subscribe());  // real time: the first line goes at once
  ASSERT_TRUE(has_sequence(position(0), 1));
  EXPECT_EQ(position(0).latest_data()->payload, position_payload(100));
  // Only the -r log keeps the server's time.
  EXPECT_FALSE(builtin.clock.claimed());
  position(0).unsubscribe();
}

TEST_F(ReadlogTest, TheDevicesOfTheMinusRLogClaimTheServerClock) {
  load("position:0 ( driver \"readlog\" )\nposition:1 ( driver \"readlog\" )\n");
  EXPECT_TRUE(builtin.clock.claimed());
  EXPECT_EQ(builtin.clock.claimant(), "position:0@6665 (readlog)");
  // Devices publish with the server clock when they give no time: log time.
  position(1).publish({1});
  EXPECT_EQ(position(1).latest_data()->timestamp, (Timestamp{1000, 0}));
}

std::string load_error(testing::BuiltinDevices& builtin, const std::string& config) {
  try {
    builtin.load(config);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(ReadlogTest, BadSettingsAreConfigErrorsNamingThem) {
  testing::BuiltinDevices plain;  // no -r
  EXPECT_NE(load_error(plain, "position:0 ( driver \"readlog\" )\n").find("test.cfg:1:1: readlog: no log file"),
            std::string::npos);
  const std::string missing = scratch.file("missing.log").string();
  EXPECT_NE(load_error(plain, "position:0 ( driver \"readlog\" filename \"" + missing + "\" )\n").find(missing),
            std::string::npos);
  testing::write_position_log(log_path, kFourLines);
  const std::string with_file = "position:0 ( driver \"readlog\" filename \"" + log_path.string() + "\" ";
  EXPECT_NE(load_error(plain, with_file + "speed 0 )\n").find("readlog: speed"), std::string::npos);
  EXPECT_NE(load_error(plain, with_file + "autorewind 2 )\n").find("autorewind must be 0 or 1"),
            std::string::npos);
  EXPECT_NE(load_error(plain, with_file + "start -1 )\n").find("readlog: start"), std::string::npos);
  std::ofstream(scratch.file("empty.log")) << log::log_file_header();
  EXPECT_NE(load_error(plain, "position:0 ( driver \"readlog\" filename \"" + scratch.file("empty.log").string() +
                                  "\" )\n")
                .find("no sync or data lines"),
            std::string::npos);
}

TEST_F(ReadlogTest, ACarmenLogIsRefusedSayingWhatReplaysIt) {
  testing::BuiltinDevices plain;
  const auto carmen = scratch.write("intel.log", "# CARMEN Logfile\nODOM 1.0 2.0 0.5 0 0 0 100.0 host 0.0\n");
  const std::string error = load_error(plain, "position:0 ( driver \"readlog\" filename \"" + carmen.string() + "\" )\n");
  EXPECT_NE(error.find("test.cfg:1:1: driver 'readlog' could not be created: " + carmen.string() +
                       " is a CARMEN log; readlog replays Player text logs: serve it with `player-log replay " +
                       carmen.string() + "`"),
            std::string::npos)
      << error;
}

TEST(FirstReplayTime, IsTheTimeOfTheFirstLineOrAnErrorNamingTheFile) {
  testing::ScratchDirectory scratch("readlog_driver_test");
  const auto log_path = scratch.file("run.log");
  testing::write_position_log(log_path, kFourLines);
  EXPECT_EQ(first_replay_time(log_path), (Timestamp{1000, 0}));
  const std::string missing = scratch.file("missing.log").string();
  try {
    (void)first_replay_time(missing);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), "cannot open " + missing + ": No such file or directory");
  }
}

TEST_F(ReadlogTest, DurationEndsEachPassThatManySecondsAfterItsStart) {
  ReadlogSettings settings;
  settings.duration = 0.5;
  load("position:0 ( driver \"readlog\" start 0.25 autorewind 1 )\n", kFourLines, 1.0, settings);
  ASSERT_TRUE(position(0).subscribe());
  // The pass is 0.25 .. 0.75 s of log: only the line at 0.5 s is position:0.
  ASSERT_TRUE(waiting_for(250ms));
  timer->set(250ms);
  ASSERT_TRUE(has_sequence(position(0), 1));
  EXPECT_EQ(position(0).latest_data()->payload, position_payload(200));
  // The line at 1.0 s is past the window: the next pass starts instead.
  ASSERT_TRUE(waiting_for(500ms));
  timer->set(500ms);
  ASSERT_TRUE(waiting_for(750ms));
  timer->set(750ms);
  ASSERT_TRUE(has_sequence(position(0), 2));
  EXPECT_EQ(position(0).latest_data()->payload, position_payload(200));
  position(0).unsubscribe();
}

TEST_F(ReadlogTest, BurstGoesAsFastAsTheSlowestReaderAndDropsNothing) {
  ReadlogSettings settings;
  settings.burst = true;
  settings.data_queue = 2;
  std::vector<LoggedSample> lines;
  for (std::uint32_t i = 0; i < 6; ++i) lines.push_back({0, {1000, i * 100000}, static_cast<int>(10 * i)});
  load("position:0 ( driver \"readlog\" )\n", lines, 1.0, settings);
  core::Device& device = position(0);
  ASSERT_EQ(device.info().limits.data_queue, 2u);
  // A reader as the server registers one: before subscribing, at sequence 0.
  device.readers().taken(7, 0);
  ASSERT_TRUE(device.subscribe());
  // The first line waits for the other subscriptions of a client to come in.
  ASSERT_TRUE(waiting_for(500ms));
  timer->set(500ms);
  // Then no pacing by the log, only by the reader: 2 lines fill its queue share.
  ASSERT_TRUE(has_sequence(device, 2));
  std::this_thread::sleep_for(30ms);
  EXPECT_EQ(device.latest_data()->sequence, 2u);
  device.readers().taken(7, 1);
  ASSERT_TRUE(has_sequence(device, 3));
  device.readers().taken(7, 3);
  ASSERT_TRUE(has_sequence(device, 5));
  // Every line is kept for the reader, in order.
  const auto owed = device.data_since(3);
  ASSERT_EQ(owed.size(), 2u);
  EXPECT_EQ(owed[0]->payload, position_payload(30));
  EXPECT_EQ(owed[1]->payload, position_payload(40));
  // A reader that leaves holds nothing back (another one, far ahead, keeps
  // the replay from pausing for want of readers).
  device.readers().taken(8, 6);
  device.readers().forget(7);
  ASSERT_TRUE(has_sequence(device, 6));
  device.unsubscribe();
}

TEST_F(ReadlogTest, BurstWaitsUntilSubscriptionsStopComingIn) {
  ReadlogSettings settings;
  settings.burst = true;
  load("position:0 ( driver \"readlog\" )\nposition:1 ( driver \"readlog\" )\n", kFourLines, 1.0, settings);
  position(0).readers().taken(7, 0);
  position(1).readers().taken(7, 0);
  ASSERT_TRUE(position(0).subscribe());
  ASSERT_TRUE(waiting_for(500ms));
  // A second subscription 400 ms later (a slow client) restarts the wait.
  timer->set(400ms);
  ASSERT_TRUE(position(1).subscribe());
  timer->set(500ms);
  ASSERT_TRUE(waiting_for(900ms));
  EXPECT_EQ(position(0).latest_data()->sequence, 0u);
  timer->set(900ms);
  // Then the whole log goes out, and each device got its lines from the first.
  ASSERT_TRUE(has_sequence(position(0), 3));
  ASSERT_TRUE(has_sequence(position(1), 1));
  const auto position0 = position(0).data_since(0);
  ASSERT_EQ(position0.size(), 3u);
  EXPECT_EQ(position0[0]->payload, position_payload(100));
  EXPECT_EQ(position(1).latest_data()->payload, position_payload(150));
  position(1).unsubscribe();
  position(0).unsubscribe();
}

}  // namespace readlog_driver_test
}  // namespace playerkit::drivers
