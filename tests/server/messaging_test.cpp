// Message-passing drivers through the server: nothing in a burst is lost.

#include <gtest/gtest.h>

#include "drivers/builtin.hpp"
#include "drivers/comms/loopback_test_support.hpp"
#include "protocol/interfaces.hpp"
#include "support/raw_client.hpp"
#include "test_server.hpp"

namespace playerkit::testing {
namespace messaging_test {

using protocol::MessageType;
using Bytes = std::vector<std::uint8_t>;

TEST(MessagingTest, EveryBroadcastOfABurstReachesEveryReader) {
  const std::uint16_t udp_port = drivers::testing::free_udp_port();
  TestServer server("comms:0 ( driver \"udpbroadcast\" addr \"127.255.255.255\" port " +
                        std::to_string(udp_port) + " )\n",
                    {}, 0, drivers::register_builtin_drivers);
  RawClient sender(server.port());
  RawClient listener(server.port());
  sender.read_banner();
  listener.read_banner();
  const protocol::DeviceAddress comms{protocol::kCommsCode, 0};
  ASSERT_EQ(sender.open(comms, 'a'), 'a');
  ASSERT_EQ(listener.open(comms, 'r'), 'r');

  constexpr int kMessages = 20;  // all within one 100 ms data round
  for (int i = 0; i < kMessages; ++i) {
    sender.send(MessageType::kCommand, comms, Bytes{'m', static_cast<std::uint8_t>(i)});
  }
  for (RawClient* client : {&listener, &sender}) {
    std::vector<Bytes> received;
    while (received.size() < kMessages) {
      auto message = client->read_message();  // throws after 5 s of silence
      if (message.type() == MessageType::kData) received.push_back(message.payload);
    }
    for (int i = 0; i < kMessages; ++i) {
      EXPECT_EQ(received[static_cast<std::size_t>(i)], (Bytes{'m', static_cast<std::uint8_t>(i)}));
    }
  }
}

}  // namespace messaging_test
}  // namespace playerkit::testing
