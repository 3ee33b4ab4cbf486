#include "drivers/comms/broadcast_socket.hpp"

#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <system_error>

#include "drivers/comms/loopback_test_support.hpp"

namespace playerkit::drivers {
namespace broadcast_socket_test {

using namespace std::chrono_literals;

TEST(Ipv4Endpoint, ParsesDottedQuads) {
  const auto endpoint = Ipv4Endpoint::parse("127.255.255.255", 6013);
  ASSERT_TRUE(endpoint.has_value());
  EXPECT_EQ(endpoint->address, 0x7FFFFFFFu);
  EXPECT_EQ(endpoint->port, 6013);
  EXPECT_EQ(endpoint->to_string(), "127.255.255.255:6013");
}

TEST(Ipv4Endpoint, RejectsAnythingElse) {
  for (const char* text : {"", "localhost", "127.0.0", "127.0.0.256", "::1", "127.0.0.1 ", "1.2.3.4.5"}) {
    EXPECT_FALSE(Ipv4Endpoint::parse(text, 1).has_value()) << '"' << text << '"';
  }
}

TEST(BroadcastSocket, TwoSocketsShareAPortAndBothHearABroadcast) {
  const std::uint16_t port = testing::free_udp_port();
  const auto first = BroadcastSocket::bind_shared(port);
  const auto second = BroadcastSocket::bind_shared(port);
  const auto destination = *Ipv4Endpoint::parse(testing::kLoopbackBroadcast, port);
  const std::array<std::uint8_t, 3> message{1, 2, 3};
  first.send_to(destination, message);

  for (const BroadcastSocket* socket : {&first, &second}) {
    ASSERT_TRUE(socket->wait_readable(5s));
    std::array<std::uint8_t, 16> buffer{};
    const auto length = socket->receive(buffer);
    ASSERT_TRUE(length.has_value());
    ASSERT_EQ(*length, 3u);
    EXPECT_EQ(buffer[0], 1);
    EXPECT_EQ(buffer[2], 3);
    EXPECT_FALSE(socket->receive(buffer).has_value());  // nothing more waiting
  }
}

TEST(BroadcastSocket, ReportsTheFullLengthOfACutDatagram) {
  const std::uint16_t port = testing::free_udp_port();
  const auto socket = BroadcastSocket::bind_shared(port);
  const testing::LoopbackPeer peer(port);
  peer.broadcast(std::string(100, 'x'));
  ASSERT_TRUE(socket.wait_readable(5s));
  std::array<std::uint8_t, 10> small{};
  EXPECT_EQ(socket.receive(small), std::optional<std::size_t>(100));
}

TEST(BroadcastSocket, WaitGivesUpAfterTheTimeout) {
  const auto socket = BroadcastSocket::bind_shared(testing::free_udp_port());
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(socket.wait_readable(20ms));
  EXPECT_GE(std::chrono::steady_clock::now() - start, 15ms);
}

TEST(BroadcastSocket, PortHeldByAnExclusiveSocketIsAnError) {
  const std::uint16_t port = testing::free_udp_port();
  const testing::UdpDescriptor exclusive;
  ASSERT_TRUE(exclusive.bind_to("0.0.0.0", port));
  EXPECT_THROW((void)BroadcastSocket::bind_shared(port), std::system_error);
}

TEST(BroadcastSocket, ClosesItsDescriptorOnceWhenDestroyed) {
  const std::uint16_t port = testing::free_udp_port();
  std::optional<BroadcastSocket> kept;
  {
    auto socket = BroadcastSocket::bind_shared(port);
    kept.emplace(std::move(socket));
  }  // the moved-from socket goes here and must leave the descriptor alone
  EXPECT_FALSE(testing::port_is_free(port));
  kept.reset();
  EXPECT_TRUE(testing::port_is_free(port));
}

}  // namespace broadcast_socket_test
}  // namespace playerkit::drivers
