// Devices whose driver's setup may block (a connect timeout, a handshake):
// the server must be able to look at them while another thread sets them up,
// and to let them go without waiting for their shutdown.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/device.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::core {
namespace device_blocking_setup_test {

using namespace std::chrono_literals;

// Bounded: a test that goes wrong fails after this instead of hanging.
constexpr auto kGateLimit = 10s;

class Gate {
 public:
  explicit Gate(bool open) : open_(open) {}
  void open() {
    {
      std::lock_guard lock(mutex_);
      open_ = true;
    }
    opened_.notify_all();
  }
  void close() {
    std::lock_guard lock(mutex_);
    open_ = false;
  }
  void wait() {
    std::unique_lock lock(mutex_);
    opened_.wait_for(lock, kGateLimit, [&] { return open_; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable opened_;
  bool open_;
};

// What the framework did to a GatedDriver, in order.
struct GatedCalls {
  Gate setup_gate{true};
  Gate shutdown_gate{true};
  std::atomic<bool> in_setup{false};
  std::atomic<bool> in_shutdown{false};
  std::atomic<int> shutdowns{0};
  std::mutex order_mutex;
  std::vector<std::string> order;

  void record(const std::string& call) {
    std::lock_guard lock(order_mutex);
    order.push_back(call);
  }
};

// setup() and shutdown() wait at their gates, as on a slow remote.
class GatedDriver : public Driver {
 public:
  GatedDriver(GatedCalls& calls, bool may_block) : calls_(calls), may_block_(may_block) {}
  void setup() override {
    calls_.in_setup = true;
    calls_.setup_gate.wait();
    calls_.record("setup");
    calls_.in_setup = false;
  }
  void shutdown() override {
    calls_.in_shutdown = true;
    calls_.shutdown_gate.wait();
    calls_.record("shutdown");
    ++calls_.shutdowns;
    calls_.in_shutdown = false;
  }
  [[nodiscard]] bool setup_may_block() const override { return may_block_; }

 private:
  GatedCalls& calls_;
  bool may_block_;
};

bool within(std::chrono::milliseconds limit, const std::function<bool()>& condition) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(1ms);
  }
  return true;
}

struct BlockingSetupFixture : ::testing::Test {
  std::unique_ptr<Device> make(bool may_block) {
    DeviceInfo info{"gated", "", protocol::Access::kAll, DeviceLimits{}, false};
    return std::make_unique<Device>(DeviceKey{6665, {protocol::kLaserCode, 0}}, info,
                                    std::make_unique<GatedDriver>(calls, may_block), clock, logger);
  }
  GatedCalls calls;
  ManualClock clock{{100, 0}};
  Logger logger;
  void SetUp() override { logger.set_sink([](LogLevel, std::string_view) {}); }
};

TEST_F(BlockingSetupFixture, CountIsReadWithoutWaitingForASetupUnderWay) {
  auto device = make(true);
  calls.setup_gate.close();
  std::atomic<bool> subscribed{false};
  std::thread setting_up([&] { subscribed = device->subscribe(); });
  ASSERT_TRUE(within(5000ms, [&] { return calls.in_setup.load(); }));
  EXPECT_EQ(device->subscriptions(), 0);
  EXPECT_TRUE(calls.in_setup) << "subscriptions() waited for setup() to end";
  calls.setup_gate.open();
  setting_up.join();
  EXPECT_TRUE(subscribed);
  EXPECT_EQ(device->subscriptions(), 1);
}

TEST_F(BlockingSetupFixture, LastUnsubscribeFromTheEventLoopLeavesTheShutdownToAThread) {
  auto device = make(true);
  ASSERT_TRUE(device->subscribe());
  calls.shutdown_gate.close();
  device->unsubscribe_from_event_loop();
  // Returned with the shutdown still waiting at its gate: it runs elsewhere.
  EXPECT_EQ(calls.shutdowns, 0);
  EXPECT_EQ(device->subscriptions(), 0);
  EXPECT_TRUE(within(5000ms, [&] { return calls.in_shutdown.load(); }));

  // A newcomer sets the driver up again only once that shutdown has ended.
  std::atomic<bool> subscribed{false};
  std::thread newcomer([&] { subscribed = device->subscribe(); });
  std::this_thread::sleep_for(20ms);
  calls.shutdown_gate.open();
  newcomer.join();
  EXPECT_TRUE(subscribed);
  EXPECT_EQ(calls.order, (std::vector<std::string>{"setup", "shutdown", "setup"}));
}

TEST_F(BlockingSetupFixture, OtherDriversAreShutDownBeforeUnsubscribeFromTheEventLoopReturns) {
  auto device = make(false);
  ASSERT_TRUE(device->subscribe());
  ASSERT_TRUE(device->subscribe());
  device->unsubscribe_from_event_loop();
  EXPECT_EQ(calls.shutdowns, 0);  // one subscription left
  device->unsubscribe_from_event_loop();
  EXPECT_EQ(calls.shutdowns, 1);
  device->unsubscribe_from_event_loop();  // one too many: ignored
  EXPECT_EQ(calls.shutdowns, 1);
}

TEST_F(BlockingSetupFixture, DestroyingTheDeviceWaitsForItsBackgroundShutdown) {
  auto device = make(true);
  ASSERT_TRUE(device->subscribe());
  calls.shutdown_gate.close();
  device->unsubscribe_from_event_loop();
  std::thread opener([&] {
    std::this_thread::sleep_for(20ms);
    calls.shutdown_gate.open();
  });
  device.reset();
  EXPECT_EQ(calls.shutdowns, 1);
  opener.join();
}

}  // namespace device_blocking_setup_test
}  // namespace playerkit::core
