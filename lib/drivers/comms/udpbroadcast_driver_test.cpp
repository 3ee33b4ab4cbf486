#include "drivers/comms/udpbroadcast_driver.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "config/errors.hpp"
#include "drivers/comms/loopback_test_support.hpp"
#include "drivers/test_support.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/comms.hpp"

namespace playerkit::drivers {
namespace udpbroadcast_driver_test {

using namespace std::chrono_literals;
using protocol::kCommsCode;
using protocol::MessageType;
using testing::eventually;

std::vector<std::uint8_t> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

std::string comms_section(int index, std::uint16_t port) {
  return "comms:" + std::to_string(index) + " ( driver \"udpbroadcast\" addr \"" +
         testing::kLoopbackBroadcast + "\" port " + std::to_string(port) + " )\n";
}

// The text of the device's latest data, decoded as player_comms_data_t.
std::string latest_text(const core::Device& device) {
  const auto sample = device.latest_data();
  if (sample->sequence == 0) return "<no data>";
  const auto data = protocol::decode<protocol::CommsData>(sample->payload);
  return {data.msg.begin(), data.msg.end()};
}

bool send_command(core::Device& device, const std::string& text) {
  const auto payload = protocol::encode(protocol::CommsCommand{bytes_of(text)});
  return device.put_command(1, payload) == core::Device::CommandStatus::kAccepted;
}

struct UdpBroadcastTest : ::testing::Test {
  std::uint16_t port = testing::free_udp_port();
  testing::BuiltinDevices builtin;
};

TEST(UdpBroadcastSpec, RegisteredAsInManual) {
  const core::DriverSpec spec = udpbroadcast_driver_spec();
  EXPECT_EQ(spec.name, "udpbroadcast");
  EXPECT_EQ(spec.interfaces, (std::vector<std::uint16_t>{kCommsCode}));
  EXPECT_EQ(spec.access, protocol::Access::kAll);
}

TEST_F(UdpBroadcastTest, DefaultsToLoopbackBroadcastOnPort6013) {
  builtin.load("comms ( driver \"udpbroadcast\" )\n");  // never subscribed: no socket
  const auto& driver = dynamic_cast<const UdpBroadcastDriver&>(builtin.device(kCommsCode).driver());
  EXPECT_EQ(driver.destination().to_string(), "127.255.255.255:6013");
}

TEST_F(UdpBroadcastTest, ReadsAddrAndPort) {
  builtin.load(comms_section(0, port));
  const auto& driver = dynamic_cast<const UdpBroadcastDriver&>(builtin.device(kCommsCode).driver());
  EXPECT_EQ(driver.destination().to_string(), "127.255.255.255:" + std::to_string(port));
}

TEST_F(UdpBroadcastTest, BadAddressIsAConfigErrorNamingIt) {
  try {
    builtin.load("comms ( driver \"udpbroadcast\" addr \"broadcast.example\" port 7000 )\n");
    FAIL() << "a bad addr was accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("broadcast.example"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("test.cfg:1"), std::string::npos) << e.what();
  }
}

TEST_F(UdpBroadcastTest, BadOptionsAreErrorsAtTheirValue) {
  const auto error_of = [this](const std::string& options) -> std::string {
    try {
      builtin.load("comms ( driver \"udpbroadcast\" " + options + " )\n");
    } catch (const config::ConfigError& e) {
      return e.what();
    }
    return "no error";
  };
  // comms ( driver "udpbroadcast" ...: the value starts at column 36.
  EXPECT_EQ(error_of("port 70000"), "test.cfg:1:36: udpbroadcast: port must be between 1 and 65535 (got 70000)");
  EXPECT_EQ(error_of("addr \"10.0.0\""),
            "test.cfg:1:36: udpbroadcast: addr \"10.0.0\" is not an IPv4 address in dotted form");
}

TEST(UdpBroadcastOptions, RejectBadAddressesAndPorts) {
  EXPECT_THROW((void)read_broadcast_destination("10.0.0", 6013), std::runtime_error);
  EXPECT_THROW((void)read_broadcast_destination("127.255.255.255", 0), std::runtime_error);
  EXPECT_THROW((void)read_broadcast_destination("127.255.255.255", 65536), std::runtime_error);
  try {
    (void)read_broadcast_destination("127.255.255.255", 70000);
    FAIL() << "port 70000 was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("70000"), std::string::npos) << e.what();
  }
}

TEST_F(UdpBroadcastTest, TwoDevicesOnOnePortBothHearAMessageIncludingTheSender) {
  builtin.load(comms_section(0, port) + comms_section(1, port));
  core::Device& sender = builtin.device(kCommsCode, 0);
  core::Device& listener = builtin.device(kCommsCode, 1);
  ASSERT_TRUE(sender.subscribe());
  ASSERT_TRUE(listener.subscribe());

  ASSERT_TRUE(send_command(sender, "hello robots"));
  EXPECT_TRUE(eventually([&] { return latest_text(listener) == "hello robots"; }))
      << latest_text(listener);
  EXPECT_TRUE(eventually([&] { return latest_text(sender) == "hello robots"; }))
      << latest_text(sender);
}

TEST_F(UdpBroadcastTest, CommandsGoOutAsOneDatagramEach) {
  builtin.load(comms_section(0, port));
  core::Device& device = builtin.device(kCommsCode);
  const testing::LoopbackPeer peer(port);
  ASSERT_TRUE(device.subscribe());

  ASSERT_TRUE(send_command(device, "first"));
  EXPECT_EQ(peer.receive(5s), std::optional<std::string>("first"));
  ASSERT_TRUE(send_command(device, "second"));
  EXPECT_EQ(peer.receive(5s), std::optional<std::string>("second"));
  const std::string binary("\x00\x01\xff", 3);
  ASSERT_TRUE(send_command(device, binary));
  EXPECT_EQ(peer.receive(5s), std::optional<std::string>(binary));
}

TEST_F(UdpBroadcastTest, CommandsWrittenJustBeforeTheLastClientLeavesStillGoOut) {
  builtin.load(comms_section(0, port));
  core::Device& device = builtin.device(kCommsCode);
  const testing::LoopbackPeer peer(port);
  ASSERT_TRUE(device.subscribe());
  ASSERT_TRUE(send_command(device, "one"));
  ASSERT_TRUE(send_command(device, "two"));
  device.unsubscribe();  // shuts the driver down, maybe before its thread looked
  EXPECT_EQ(peer.receive(5s), std::optional<std::string>("one"));
  EXPECT_EQ(peer.receive(5s), std::optional<std::string>("two"));
}

TEST_F(UdpBroadcastTest, EveryDatagramHeardIsPublished) {
  builtin.load(comms_section(0, port));
  core::Device& device = builtin.device(kCommsCode);
  ASSERT_TRUE(device.subscribe());
  const testing::LoopbackPeer peer(port);

  peer.broadcast("one");
  ASSERT_TRUE(eventually([&] { return latest_text(device) == "one"; })) << latest_text(device);
  peer.broadcast("two");
  ASSERT_TRUE(eventually([&] { return latest_text(device) == "two"; })) << latest_text(device);
  EXPECT_EQ(device.latest_data()->sequence, 2u);
}

TEST_F(UdpBroadcastTest, EmptyAndOversizedDatagramsAreNotPublished) {
  builtin.load(comms_section(0, port));
  core::Device& device = builtin.device(kCommsCode);
  ASSERT_TRUE(device.subscribe());
  const testing::LoopbackPeer peer(port);

  peer.broadcast(std::string());
  peer.broadcast(std::string(protocol::kMaxPayloadSize + 1, 'x'));
  peer.broadcast("fits");
  ASSERT_TRUE(eventually([&] { return latest_text(device) == "fits"; })) << latest_text(device);
  EXPECT_EQ(device.latest_data()->sequence, 1u);  // loopback keeps the order: the others came first
}

TEST_F(UdpBroadcastTest, LargestPayloadGoesThroughWhole) {
  builtin.load(comms_section(0, port));
  core::Device& device = builtin.device(kCommsCode);
  ASSERT_TRUE(device.subscribe());
  const std::string largest(protocol::kMaxPayloadSize, 'L');
  ASSERT_TRUE(send_command(device, largest));
  EXPECT_TRUE(eventually([&] { return latest_text(device) == largest; }));
}

TEST_F(UdpBroadcastTest, CommandLeftFromBeforeTheSubscriptionIsNotSent) {
  builtin.load(comms_section(0, port));
  core::Device& device = builtin.device(kCommsCode);
  const testing::LoopbackPeer peer(port);
  ASSERT_TRUE(send_command(device, "stale"));
  ASSERT_TRUE(device.subscribe());
  ASSERT_TRUE(send_command(device, "fresh"));
  EXPECT_EQ(peer.receive(5s), std::optional<std::string>("fresh"));
}

TEST_F(UdpBroadcastTest, RequestsAreAnsweredNack) {
  builtin.load(comms_section(0, port));
  core::Device& device = builtin.device(kCommsCode);
  ASSERT_TRUE(device.subscribe());
  ASSERT_EQ(device.enqueue_request(testing::make_request(kCommsCode, {1, 2})),
            core::Device::RequestStatus::kQueued);
  std::vector<core::Reply> replies;
  ASSERT_TRUE(eventually([&] {
    for (auto& reply : device.take_replies()) replies.push_back(std::move(reply));
    return !replies.empty();
  }));
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0].type, MessageType::kNack);
  EXPECT_EQ(replies[0].client, 1u);
}

TEST_F(UdpBroadcastTest, ShutdownIsPromptAndReleasesThePort) {
  builtin.load(comms_section(0, port) + comms_section(1, port));
  core::Device& first = builtin.device(kCommsCode, 0);
  ASSERT_TRUE(first.subscribe());
  EXPECT_FALSE(testing::port_is_free(port));

  const auto start = std::chrono::steady_clock::now();
  first.unsubscribe();
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1s);
  EXPECT_TRUE(testing::port_is_free(port));

  // Another device, or the same one again, can listen there now.
  core::Device& second = builtin.device(kCommsCode, 1);
  ASSERT_TRUE(second.subscribe());
  ASSERT_TRUE(send_command(second, "after"));
  EXPECT_TRUE(eventually([&] { return latest_text(second) == "after"; }));
  ASSERT_TRUE(first.subscribe());
  ASSERT_TRUE(send_command(first, "again"));
  EXPECT_TRUE(eventually([&] { return latest_text(first) == "again"; }));
}

TEST_F(UdpBroadcastTest, PortHeldByAnotherProgramRefusesTheSubscription) {
  struct ErrorLog {
    std::mutex mutex;
    std::vector<std::string> lines;
  };
  // Shared with the sink, which lives as long as the fixture's logger.
  const auto errors = std::make_shared<ErrorLog>();
  builtin.logger.set_sink([errors](core::LogLevel level, std::string_view line) {
    std::lock_guard lock(errors->mutex);
    if (level == core::LogLevel::kError) errors->lines.emplace_back(line);
  });
  builtin.load(comms_section(0, port));
  const testing::UdpDescriptor exclusive;  // does not ask to share the port
  ASSERT_TRUE(exclusive.bind_to("0.0.0.0", port));

  core::Device& device = builtin.device(kCommsCode);
  EXPECT_FALSE(device.subscribe());
  EXPECT_EQ(device.subscriptions(), 0);
  std::lock_guard lock(errors->mutex);
  ASSERT_EQ(errors->lines.size(), 1u);
  EXPECT_NE(errors->lines[0].find(std::to_string(port)), std::string::npos) << errors->lines[0];
}

}  // namespace udpbroadcast_driver_test
}  // namespace playerkit::drivers
