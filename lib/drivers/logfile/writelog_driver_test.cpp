#include "drivers/logfile/writelog_driver.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "config/errors.hpp"
#include "core/clock.hpp"
#include "drivers/logfile/logfile_test_support.hpp"
#include "drivers/logfile/readlog_driver.hpp"
#include "drivers/test_support.hpp"
#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {
namespace writelog_driver_test {

using namespace std::chrono_literals;
using protocol::kNullCode;
using protocol::kPositionCode;
using protocol::Timestamp;
using testing::eventually;
using testing::position_payload;

// A device that publishes only what the test publishes on it.
core::DriverSpec test_source_spec() {
  core::DriverSpec spec;
  spec.name = "testsource";
  spec.interfaces = {kPositionCode};
  spec.access = protocol::Access::kRead;
  spec.factory = [](const core::DriverContext&) { return std::make_unique<core::Driver>(); };
  spec.summary = "test data source";
  return spec;
}

// A source that publishes in its own setup(), as readlog does with its first line.
class EagerSource final : public core::Driver {
 public:
  void setup() override { device().publish(position_payload(42)); }
};

struct WritelogTest : ::testing::Test {
  WritelogTest() {
    builtin.registry.add(test_source_spec());
    core::DriverSpec eager = test_source_spec();
    eager.name = "eagersource";
    eager.factory = [](const core::DriverContext&) { return std::make_unique<EagerSource>(); };
    builtin.registry.add(std::move(eager));
  }

  void load_recorder(const std::string& extra = "") {
    builtin.load("position:0 ( driver \"testsource\" )\nposition:1 ( driver \"testsource\" )\n"
                 "null:0 ( driver \"writelog\" filename \"" + log_path.string() +
                 "\" devices [\"position:0\" \"position:1\"] " + extra + ")\n");
  }
  core::Device& position(std::uint16_t index) { return builtin.device(kPositionCode, index); }
  core::Device& recorder() { return builtin.device(kNullCode); }

  testing::ScratchDirectory scratch;
  std::filesystem::path log_path = scratch.file("recorded.log");
  testing::BuiltinDevices builtin;
};

TEST_F(WritelogTest, RecordsEverySampleOfTheListedDevicesLineByLine) {
  load_recorder();
  ASSERT_TRUE(recorder().subscribe());
  EXPECT_EQ(position(0).subscriptions(), 1);  // the recorder holds its sources
  EXPECT_EQ(position(1).subscriptions(), 1);

  position(0).publish(position_payload(10), Timestamp{500, 1000});
  // Flushed as written: the line is in the file while the recorder still runs.
  ASSERT_TRUE(eventually([&] { return testing::read_data_lines(log_path).size() == 1; }));
  position(1).publish(position_payload(20), Timestamp{500, 2000});
  position(0).publish(position_payload(30), Timestamp{500, 3000});
  ASSERT_TRUE(eventually([&] { return testing::read_data_lines(log_path).size() == 3; }));

  const auto lines = testing::read_data_lines(log_path);
  const std::vector<std::pair<std::uint16_t, std::int32_t>> expected{{0, 10}, {1, 20}, {0, 30}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_TRUE(lines[i].device.has_value());
    EXPECT_EQ(*lines[i].device, (protocol::DeviceAddress{kPositionCode, expected[i].first}));
    EXPECT_EQ(lines[i].message.payload, position_payload(expected[i].second)) << i;
    EXPECT_EQ(lines[i].data_time, (Timestamp{500, static_cast<std::uint32_t>(1000 * (i + 1))}));
    EXPECT_EQ(lines[i].port, testing::kTestPort);
  }
  recorder().unsubscribe();
  EXPECT_EQ(position(0).subscriptions(), 0);
  EXPECT_EQ(position(1).subscriptions(), 0);
}

TEST_F(WritelogTest, ShutdownWritesEverythingReceived) {
  load_recorder();
  ASSERT_TRUE(recorder().subscribe());
  constexpr int kSamples = 300;
  for (int i = 0; i < kSamples; ++i) {
    position(i % 2 == 0 ? 0 : 1).publish(position_payload(i), Timestamp{600, static_cast<std::uint32_t>(i)});
  }
  recorder().unsubscribe();  // at once: what the thread has not written yet must still go in
  const auto lines = testing::read_data_lines(log_path);
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(kSamples));
  for (int i = 0; i < kSamples; ++i) {
    EXPECT_EQ(lines[static_cast<std::size_t>(i)].message.payload, position_payload(i)) << i;
  }
  // Nothing after shutdown.
  position(0).publish(position_payload(-1));
  EXPECT_EQ(testing::read_data_lines(log_path).size(), static_cast<std::size_t>(kSamples));
}

TEST_F(WritelogTest, EachSetUpStartsANewFileAndOnlyNewSamplesGoIn) {
  load_recorder();
  position(0).publish(position_payload(1));  // before recording: not recorded
  ASSERT_TRUE(recorder().subscribe());
  position(0).publish(position_payload(2));
  recorder().unsubscribe();
  ASSERT_EQ(testing::read_data_lines(log_path).size(), 1u);
  ASSERT_TRUE(recorder().subscribe());  // truncates, as 1.5 did
  recorder().unsubscribe();
  EXPECT_TRUE(testing::read_data_lines(log_path).empty());
}

TEST_F(WritelogTest, RecordsWhatASourcePublishesInItsSetUp) {
  builtin.load("position:0 ( driver \"eagersource\" )\n"
               "null:0 ( driver \"writelog\" filename \"" + log_path.string() +
               "\" devices [\"position:0\"] )\n");
  ASSERT_TRUE(recorder().subscribe());
  recorder().unsubscribe();
  const auto lines = testing::read_data_lines(log_path);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].message.payload, position_payload(42));
}

TEST_F(WritelogTest, AlwaysonRecordsFromStartUp) {
  load_recorder("alwayson 1");
  builtin.devices.start_alwayson();
  position(1).publish(position_payload(7));
  ASSERT_TRUE(eventually([&] { return testing::read_data_lines(log_path).size() == 1; }));
  builtin.devices.shutdown_all();
  EXPECT_EQ(testing::read_data_lines(log_path).size(), 1u);
}

TEST_F(WritelogTest, AnswersRequestsNack) {
  load_recorder();
  ASSERT_TRUE(recorder().subscribe());
  ASSERT_EQ(recorder().enqueue_request(testing::make_request(kNullCode, {1})),
            core::Device::RequestStatus::kQueued);
  std::vector<core::Reply> replies;
  ASSERT_TRUE(eventually([&] {
    for (core::Reply& reply : recorder().take_replies()) replies.push_back(std::move(reply));
    return !replies.empty();
  }));
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0].type, protocol::MessageType::kNack);
  recorder().unsubscribe();
}

TEST_F(WritelogTest, RecordedLogReplaysEqual) {
  // The log's time column is the server's clock when a sample was recorded.
  // On the wall clock twenty samples published in a burst come microseconds
  // apart (under a microsecond each in an optimised build), a rate readlog
  // rightly calls absurd; a robot's log runs at 10 Hz, and so does this one.
  auto recording_clock = std::make_shared<core::ManualClock>();
  builtin.clock.claim(recording_clock, "the test");
  load_recorder();
  ASSERT_TRUE(recorder().subscribe());
  const auto stamp = [](int i) {
    return Timestamp{static_cast<std::uint32_t>(700 + i / 10), static_cast<std::uint32_t>(i % 10 * 100'000)};
  };
  for (int i = 0; i < 20; ++i) {
    recording_clock->set(stamp(i));
    position(0).publish(position_payload(i * 7), stamp(i));
  }
  recorder().unsubscribe();

  // Replay it through readlog with time pushed forward, collecting every sample.
  struct Collector : core::DeviceListener {
    void data_published(const core::Device& device) override {
      std::lock_guard lock(mutex);
      samples.push_back(*device.latest_data());
    }
    void replies_ready(const core::Device&) override {}
    std::mutex mutex;
    std::vector<core::DataSample> samples;
  } collector;
  auto timer = std::make_shared<testing::ManualReplayTimer>();
  testing::BuiltinDevices replay;
  ReadlogSettings settings;
  settings.log = log_path;
  settings.timer = timer;
  replay.registry.add(readlog_driver_spec(std::move(settings)));
  replay.load("position:0 ( driver \"readlog\" )\n");
  core::Device& replayed = replay.device(kPositionCode);
  replayed.add_listener(&collector);
  ASSERT_TRUE(replayed.subscribe());
  ASSERT_TRUE(eventually([&] {
    timer->set(timer->now() + 1h);  // whatever the replay waits for is due
    std::lock_guard lock(collector.mutex);
    return collector.samples.size() == 20;
  }));
  replayed.unsubscribe();
  replayed.remove_listener(&collector);
  for (std::size_t i = 0; i < 20; ++i) {
    EXPECT_EQ(collector.samples[i].payload, position_payload(static_cast<std::int32_t>(i * 7)));
    EXPECT_EQ(collector.samples[i].timestamp, stamp(static_cast<int>(i)));
  }
}

std::string load_error(testing::BuiltinDevices& builtin, const std::string& config) {
  try {
    builtin.load(config);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(WritelogTest, BadConfigurationIsRefusedWithItsLocation) {
  EXPECT_NE(load_error(builtin, "null:0 ( driver \"writelog\" devices [\"position:0\" \"lazer:0\"] )\n")
                .find("test.cfg:1:50: writelog: devices entry \"lazer:0\""),
            std::string::npos);
  testing::BuiltinDevices other;
  EXPECT_NE(load_error(other, "null:0 ( driver \"writelog\" )\n").find("no devices to record"),
            std::string::npos);
}

TEST_F(WritelogTest, AFilenameThatCouldNeverBeWrittenIsRefusedWhenLoaded) {
  const std::string sources = "position:0 ( driver \"testsource\" )\n";
  const auto refused = [&](const std::string& filename) {
    testing::BuiltinDevices other;
    other.registry.add(test_source_spec());
    return load_error(other, sources + "null:0 ( driver \"writelog\" filename \"" + filename +
                                 "\" devices [\"position:0\"] )\n");
  };
  const std::string directory = scratch.path().string();
  EXPECT_EQ(refused(directory), "test.cfg:2:37: writelog: filename \"" + directory + "\" is a directory");
  const std::string nowhere = scratch.file("no-such-directory/run.log").string();
  EXPECT_EQ(refused(nowhere), "test.cfg:2:37: writelog: filename \"" + nowhere + "\": directory " +
                                  scratch.file("no-such-directory").string() + " does not exist");
  const auto plain_file = scratch.write("plain", "");
  EXPECT_EQ(refused(plain_file.string() + "/run.log"), "test.cfg:2:37: writelog: filename \"" + plain_file.string() +
                                                          "/run.log\": " + plain_file.string() + " is not a directory");
  // Nothing is created while checking.
  EXPECT_EQ(refused(log_path.string()), "no error");
  EXPECT_FALSE(std::filesystem::exists(log_path));
}

TEST_F(WritelogTest, SetUpFailsWhenASourceIsMissingAndReleasesTheOthers) {
  builtin.load("position:0 ( driver \"testsource\" )\n"
               "null:0 ( driver \"writelog\" filename \"" + log_path.string() +
               "\" devices [\"position:0\" \"position:5\"] )\n");
  EXPECT_FALSE(recorder().subscribe());
  EXPECT_EQ(position(0).subscriptions(), 0);
}

TEST_F(WritelogTest, AGzFilenameIsRecordedGzipCompressed) {
  log_path = scratch.file("recorded.log.gz");
  load_recorder();
  ASSERT_TRUE(recorder().subscribe());
  for (int i = 0; i < 50; ++i) position(0).publish(position_payload(i), Timestamp{700, static_cast<std::uint32_t>(i)});
  recorder().unsubscribe();
  std::ifstream raw(log_path, std::ios::binary);
  std::string magic(2, '\0');
  raw.read(magic.data(), 2);
  EXPECT_EQ(magic, "\x1f\x8b");
  auto in = log::open_log_input(log_path);
  log::TextLogReader reader(*in, log_path.string());
  std::size_t data_lines = 0;
  for (int guard = 0; guard < 1000; ++guard) {
    const auto line = reader.next();
    if (!line) break;
    if (std::holds_alternative<log::DataLine>(*line)) ++data_lines;
  }
  EXPECT_EQ(data_lines, 50U);
  EXPECT_FALSE(in->error());
  EXPECT_EQ(reader.malformed_count(), 0U);
}

TEST(WritelogDefaults, NullSectionsWithoutDriverAreWritelog) {
  testing::BuiltinDevices builtin;
  builtin.load("null ( devices [\"position:0\"] )\n");
  EXPECT_EQ(builtin.device(kNullCode).info().driver_name, "writelog");
  EXPECT_EQ(builtin.device(kNullCode).info().access, protocol::Access::kRead);
}

}  // namespace writelog_driver_test
}  // namespace playerkit::drivers
