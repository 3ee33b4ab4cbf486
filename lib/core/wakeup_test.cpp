#include "core/wakeup.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <thread>

#include "core/device.hpp"
#include "core/test_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::core {
namespace wakeup_test {

using namespace std::chrono_literals;
// Far enough that a wait reaching it is a failure the test names, not a pass.
const auto kNever = [] { return Wakeup::Clock::now() + 30s; };

TEST(Wakeup, ANotifyBeforeTheWaitIsRemembered) {
  Wakeup wakeup;
  wakeup.notify();
  wakeup.notify();
  EXPECT_TRUE(wakeup.wait(kNever()).notified);
  // Consumed: a second look finds nothing.
  EXPECT_FALSE(wakeup.wait(Wakeup::Clock::now()).notified);
}

TEST(Wakeup, ANotifyFromAnotherThreadEndsTheWait) {
  Wakeup wakeup;
  std::jthread other([&] { wakeup.notify(); });
  const auto woken = wakeup.wait(kNever());
  EXPECT_TRUE(woken.notified);
  EXPECT_FALSE(woken.readable);
}

TEST(Wakeup, InputOnTheOtherDescriptorEndsTheWait) {
  int pipe_ends[2];
  ASSERT_EQ(::pipe(pipe_ends), 0);
  Wakeup wakeup;
  EXPECT_FALSE(wakeup.wait(Wakeup::Clock::now(), pipe_ends[0]).readable);
  ASSERT_EQ(::write(pipe_ends[1], "x", 1), 1);
  const auto woken = wakeup.wait(kNever(), pipe_ends[0]);
  EXPECT_TRUE(woken.readable);
  EXPECT_FALSE(woken.notified);
  ::close(pipe_ends[0]);
  ::close(pipe_ends[1]);
}

TEST(Wakeup, APastDeadlineOnlyLooks) {
  Wakeup wakeup;
  const auto woken = wakeup.wait(Wakeup::Clock::now() - 1s);
  EXPECT_FALSE(woken.notified);
  EXPECT_FALSE(woken.readable);
}

struct DeviceWakeup : ::testing::Test {
  testing::CallCounts counts;
  ManualClock clock{{100, 0}};
  Logger logger;
  std::shared_ptr<Wakeup> wakeup = std::make_shared<Wakeup>();
  Device device{DeviceKey{6665, {protocol::kPositionCode, 0}},
                DeviceInfo{"counting", "", protocol::Access::kAll, DeviceLimits{1}, false},
                std::make_unique<testing::CountingDriver>(counts), clock, logger};
};

TEST_F(DeviceWakeup, ACommandWakesTheDriver) {
  device.set_wakeup(wakeup);
  ASSERT_EQ(device.put_command(1, protocol::encode(protocol::PositionCommand{})), Device::CommandStatus::kAccepted);
  EXPECT_TRUE(wakeup->wait(kNever()).notified);
}

TEST_F(DeviceWakeup, AQueuedRequestWakesTheDriverARefusedOneDoesNot) {
  device.set_wakeup(wakeup);
  ASSERT_EQ(device.enqueue_request(Request{1, device.address(), {1}, {}}), Device::RequestStatus::kQueued);
  EXPECT_TRUE(wakeup->wait(kNever()).notified);
  ASSERT_EQ(device.enqueue_request(Request{1, device.address(), {1}, {}}), Device::RequestStatus::kQueueFull);
  EXPECT_FALSE(wakeup->wait(Wakeup::Clock::now()).notified);
}

TEST_F(DeviceWakeup, NothingIsNotifiedOnceTheDriverLetsGo) {
  device.set_wakeup(wakeup);
  device.set_wakeup(nullptr);
  ASSERT_EQ(device.put_command(1, protocol::encode(protocol::PositionCommand{})), Device::CommandStatus::kAccepted);
  EXPECT_FALSE(wakeup->wait(Wakeup::Clock::now()).notified);
}

}  // namespace wakeup_test
}  // namespace playerkit::core
