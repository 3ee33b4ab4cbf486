#include "core/device.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "core/test_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::core {
namespace device_test {

using protocol::Access;
using protocol::MessageType;
using testing::CallCounts;
using testing::CountingDriver;

struct DeviceFixture : ::testing::Test {
  std::unique_ptr<Device> make(Access access = Access::kAll, bool refuse = false,
                               std::uint16_t interface = protocol::kPositionCode,
                               std::size_t queue = 2) {
    DeviceInfo info{"counting", "", access, DeviceLimits{queue}, false};
    return std::make_unique<Device>(DeviceKey{6665, {interface, 0}}, info,
                                    std::make_unique<CountingDriver>(counts, refuse), clock, logger);
  }
  CallCounts counts;
  ManualClock clock{{100, 0}};
  Logger logger;
  void SetUp() override { logger.set_sink([](LogLevel, std::string_view) {}); }
};

TEST_F(DeviceFixture, FirstSubscriberSetsUpLastShutsDown) {
  auto device = make();
  EXPECT_TRUE(device->subscribe());
  EXPECT_TRUE(device->subscribe());
  EXPECT_EQ(counts.setup, 1);
  device->unsubscribe();
  EXPECT_EQ(counts.shutdown, 0);
  device->unsubscribe();
  EXPECT_EQ(counts.shutdown, 1);
  EXPECT_EQ(device->subscriptions(), 0);
  device->unsubscribe();  // one too many: ignored
  EXPECT_EQ(counts.shutdown, 1);
  EXPECT_TRUE(device->subscribe());
  EXPECT_EQ(counts.setup, 2);
}

TEST_F(DeviceFixture, UnavailableDeviceRefusesNewSubscriptionsAndKeepsHeldOnes) {
  auto device = make();
  ASSERT_TRUE(device->subscribe());
  EXPECT_TRUE(device->available());
  device->set_available(false, "remote localhost:6665 went away");
  EXPECT_FALSE(device->available());
  EXPECT_FALSE(device->subscribe());
  EXPECT_EQ(device->subscriptions(), 1);  // the one held is kept
  EXPECT_EQ(counts.setup, 1);
  device->set_available(true);
  EXPECT_TRUE(device->subscribe());
  EXPECT_EQ(device->subscriptions(), 2);
}

TEST_F(DeviceFixture, RefusedSubscriptionIsLoggedWithTheReason) {
  std::vector<std::string> lines;
  logger.set_sink([&](LogLevel, std::string_view line) { lines.emplace_back(line); });
  auto device = make();
  ASSERT_TRUE(device->subscribe());
  device->set_available(false, "remote localhost:6665 went away");
  EXPECT_FALSE(device->subscribe());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("position:0@6665"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("remote localhost:6665 went away"), std::string::npos) << lines[0];
}

TEST_F(DeviceFixture, EverySetupStartsAvailable) {
  auto device = make();
  ASSERT_TRUE(device->subscribe());
  device->set_available(false);
  device->unsubscribe();  // shut down while unavailable
  EXPECT_TRUE(device->subscribe());  // set up afresh: the driver decides again
  EXPECT_TRUE(device->available());
  EXPECT_TRUE(device->subscribe());
  EXPECT_EQ(counts.setup, 2);
}

TEST_F(DeviceFixture, RemovingAListenerWaitsForItsCallbackUnderWayOnAnotherThread) {
  struct BlockingListener : DeviceListener {
    std::atomic<bool> inside{false};
    std::atomic<bool> release{false};
    void data_published(const Device&) override {
      inside = true;
      while (!release) std::this_thread::yield();
    }
    void replies_ready(const Device&) override {}
  };
  auto device = make();
  BlockingListener listener;
  device->add_listener(&listener);
  std::thread publisher([&] { device->publish({1}, {}); });
  while (!listener.inside) std::this_thread::yield();
  std::atomic<bool> removed{false};
  std::thread remover([&] {
    device->remove_listener(&listener);
    removed = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(removed);  // the callback is still running: the listener must stay alive
  listener.release = true;
  remover.join();
  publisher.join();
  EXPECT_TRUE(removed);
}

TEST_F(DeviceFixture, AListenerMayRemoveItselfFromItsOwnCallback) {
  struct SelfRemovingListener : DeviceListener {
    Device* device = nullptr;
    int calls = 0;
    void data_published(const Device&) override {
      ++calls;
      device->remove_listener(this);
    }
    void replies_ready(const Device&) override {}
  };
  auto device = make();
  SelfRemovingListener listener;
  listener.device = device.get();
  device->add_listener(&listener);
  device->publish({1}, {});
  device->publish({2}, {});
  EXPECT_EQ(listener.calls, 1);
}

TEST_F(DeviceFixture, RefusedSetupLeavesCountAtZero) {
  auto device = make(Access::kAll, /*refuse=*/true);
  EXPECT_FALSE(device->subscribe());
  EXPECT_EQ(device->subscriptions(), 0);
  EXPECT_FALSE(device->subscribe());
  EXPECT_EQ(counts.setup, 2);
  EXPECT_EQ(counts.shutdown, 0);
}

TEST_F(DeviceFixture, DestructionShutsDownASubscribedDriver) {
  auto device = make();
  ASSERT_TRUE(device->subscribe());
  device.reset();
  EXPECT_EQ(counts.shutdown, 1);
}

TEST_F(DeviceFixture, PublishKeepsOnlyTheLatestSampleAndCountsSequence) {
  auto device = make();
  EXPECT_EQ(device->latest_data()->sequence, 0u);
  device->publish({1, 2, 3}, {5, 6});
  device->publish({4});
  const auto sample = device->latest_data();
  EXPECT_EQ(sample->payload, (std::vector<std::uint8_t>{4}));
  EXPECT_EQ(sample->timestamp, (Timestamp{100, 0}));  // the device's clock
  EXPECT_EQ(sample->sequence, 2u);
}

TEST_F(DeviceFixture, CommandsOverwriteAndAreTakenOnce) {
  auto device = make();
  protocol::PositionCommand forward;
  forward.xspeed = 200;
  protocol::PositionCommand turn;
  turn.yawspeed = 30;
  const auto forward_bytes = protocol::encode(forward);
  const auto turn_bytes = protocol::encode(turn);
  EXPECT_EQ(device->put_command(1, forward_bytes), Device::CommandStatus::kAccepted);
  EXPECT_EQ(device->put_command(2, turn_bytes), Device::CommandStatus::kAccepted);
  auto taken = device->take_command();
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->payload, turn_bytes);
  EXPECT_EQ(taken->client, 2u);
  EXPECT_FALSE(device->take_command());
  EXPECT_TRUE(device->latest_command());
}

TEST_F(DeviceFixture, CommandOfTheWrongSizeIsRefused) {
  auto device = make();
  std::vector<std::uint8_t> too_long(protocol::PositionCommand::kWireSize + 1, 0);
  std::vector<std::uint8_t> too_short(3, 0);
  EXPECT_EQ(device->put_command(1, too_long), Device::CommandStatus::kWrongSize);
  EXPECT_EQ(device->put_command(1, too_short), Device::CommandStatus::kWrongSize);
  EXPECT_FALSE(device->take_command());
}

TEST_F(DeviceFixture, ReadOnlyDeviceAndInterfaceWithoutCommandRefuseCommands) {
  auto read_only = make(Access::kRead);
  const auto bytes = protocol::encode(protocol::PositionCommand{});
  EXPECT_EQ(read_only->put_command(1, bytes), Device::CommandStatus::kReadOnly);
  auto laser = make(Access::kAll, false, protocol::kLaserCode);  // laser has no command
  EXPECT_EQ(laser->put_command(1, std::vector<std::uint8_t>{1}), Device::CommandStatus::kReadOnly);
}

TEST_F(DeviceFixture, RequestQueueIsBoundedAndEveryRequestIsAnswered) {
  auto device = make(Access::kAll, false, protocol::kPositionCode, /*queue=*/2);
  EXPECT_EQ(device->enqueue_request({7, {4, 0}, {1, 9}, {}}), Device::RequestStatus::kQueued);
  EXPECT_EQ(device->enqueue_request({8, {4, 0}, {42}, {}}), Device::RequestStatus::kQueued);
  EXPECT_EQ(device->enqueue_request({9, {4, 0}, {1}, {}}), Device::RequestStatus::kQueueFull);
  ASSERT_TRUE(device->subscribe());
  device->update();
  EXPECT_EQ(device->pending_requests(), 0u);
  const auto replies = device->take_replies();
  ASSERT_EQ(replies.size(), 2u);
  EXPECT_EQ(replies[0].client, 7u);
  EXPECT_EQ(replies[0].type, MessageType::kAck);
  EXPECT_EQ(replies[0].payload, (std::vector<std::uint8_t>{1, 9}));
  EXPECT_EQ(replies[1].client, 8u);
  EXPECT_EQ(replies[1].type, MessageType::kNack);  // unknown subtype: default answer
  EXPECT_EQ(counts.update, 1);
  EXPECT_TRUE(device->take_replies().empty());
}

TEST_F(DeviceFixture, AThrowingRequestHandlerAnswersNack) {
  auto device = make();
  device->enqueue_request({3, {4, 0}, {2}, {}});
  device->service_requests();
  const auto replies = device->take_replies();
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0].type, MessageType::kNack);
}

struct RecordingListener : DeviceListener {
  std::atomic<int> data{0};
  std::atomic<int> replies{0};
  void data_published(const Device&) override { ++data; }
  void replies_ready(const Device&) override { ++replies; }
};

TEST_F(DeviceFixture, ListenersHearOfDataAndReplies) {
  auto device = make();
  RecordingListener listener;
  device->add_listener(&listener);
  device->publish({1});
  device->enqueue_request({1, {4, 0}, {1}, {}});
  device->service_requests();
  EXPECT_EQ(listener.data, 1);
  EXPECT_EQ(listener.replies, 1);
  device->remove_listener(&listener);
  device->publish({2});
  EXPECT_EQ(listener.data, 1);
}

// A driver with its own thread publishes a counter until it is shut down.
class TickingDriver : public ThreadedDriver {
 public:
  std::atomic<int> opened{0};
  std::atomic<int> closed{0};

 protected:
  void open() override { ++opened; }
  void close() override { ++closed; }
  void run(std::stop_token stop) override {
    std::uint8_t tick = 0;
    while (sleep_for(stop, std::chrono::milliseconds(1))) {
      device().publish({tick++});
      device().service_requests();
    }
  }
};

TEST_F(DeviceFixture, ThreadedDriverRunsBetweenSetupAndShutdown) {
  auto driver = std::make_unique<TickingDriver>();
  TickingDriver* ticking = driver.get();
  Device device(DeviceKey{6665, {protocol::kPositionCode, 0}},
                DeviceInfo{"ticking", "", Access::kAll, {}, false}, std::move(driver), clock, logger);
  ASSERT_TRUE(device.subscribe());
  EXPECT_EQ(ticking->opened, 1);
  device.enqueue_request({5, {4, 0}, {1}, {}});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while ((device.latest_data()->sequence < 3 || device.pending_requests() > 0) &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_GE(device.latest_data()->sequence, 3u);
  device.update();  // the server's loop must not touch a threaded driver's requests
  EXPECT_EQ(device.take_replies().size(), 1u);
  device.unsubscribe();
  EXPECT_EQ(ticking->closed, 1);
  const auto after_stop = device.latest_data()->sequence;
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(device.latest_data()->sequence, after_stop);
}

TEST(DeviceKeyTest, PrintsAddressAndPort) {
  EXPECT_EQ(to_string(DeviceKey{6666, {protocol::kLaserCode, 1}}), "laser:1@6666");
}

}  // namespace device_test
}  // namespace playerkit::core

namespace playerkit::core {
namespace device_test {

TEST_F(DeviceFixture, QueuedDeviceKeepsItsLastSamplesInOrder) {
  DeviceInfo info{"queued", "", Access::kRead, DeviceLimits{1, 3}, false};
  Device device(DeviceKey{6665, {protocol::kCommsCode, 0}}, info,
                std::make_unique<CountingDriver>(counts), clock, logger);
  EXPECT_TRUE(device.queues_data());
  for (std::uint8_t i = 1; i <= 5; ++i) device.publish({i});
  const auto all = device.data_since(0);
  ASSERT_EQ(all.size(), 3u);  // the two oldest fell out
  EXPECT_EQ(all[0]->payload, (std::vector<std::uint8_t>{3}));
  EXPECT_EQ(all[2]->payload, (std::vector<std::uint8_t>{5}));
  EXPECT_EQ(device.data_since(4).size(), 1u);
  EXPECT_TRUE(device.data_since(5).empty());
}

TEST_F(DeviceFixture, SensorDeviceKeepsNoHistory) {
  auto device = make();
  device->publish({1});
  EXPECT_FALSE(device->queues_data());
  EXPECT_TRUE(device->data_since(0).empty());
}

}  // namespace device_test
}  // namespace playerkit::core

namespace playerkit::core {
namespace device_test {

TEST_F(DeviceFixture, CommandQueueDeviceHandsOutEveryCommandOldestFirst) {
  DeviceInfo info{"queued", "", Access::kAll, DeviceLimits{1, 0, 2}, false};
  Device device(DeviceKey{6665, {protocol::kCommsCode, 0}}, info,
                std::make_unique<CountingDriver>(counts), clock, logger);
  for (std::uint8_t i = 1; i <= 3; ++i) {
    EXPECT_EQ(device.put_command(1, std::vector<std::uint8_t>{i}), Device::CommandStatus::kAccepted);
  }
  EXPECT_EQ(device.take_command()->payload, (std::vector<std::uint8_t>{2}));  // 1 was dropped
  EXPECT_EQ(device.take_command()->payload, (std::vector<std::uint8_t>{3}));
  EXPECT_FALSE(device.take_command());
}

}  // namespace device_test
}  // namespace playerkit::core
