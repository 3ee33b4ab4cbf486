#include "links/tcp_link.hpp"

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <atomic>
#include <thread>

#include "links/link_error.hpp"
#include "links/links_test_support.hpp"
#include "links/tcp_listener.hpp"

namespace playerkit::links {
namespace tcp_link_test {

using namespace test_support;

struct Connected {
  TcpListener listener{"127.0.0.1", 0};
  std::unique_ptr<TcpLink> driver;
  std::unique_ptr<TcpLink> device;

  Connected() {
    driver = TcpLink::connect("127.0.0.1", listener.port(), deadline_in(kPatience));
    device = listener.accept(deadline_in(kPatience));
    if (!device) throw std::runtime_error("no connection accepted");
  }
};

LinkError connect_error(const std::string& host, std::uint16_t port, Deadline deadline) {
  try {
    TcpLink::connect(host, port, deadline);
  } catch (const LinkError& error) {
    return error;
  }
  ADD_FAILURE() << "connected to " << host << ":" << port;
  return LinkError(LinkErrorKind::io_error, "", "connected");
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(TcpLink, RoundTripBothWays) {
  Connected pair;
  EXPECT_EQ(pair.driver->describe(), "tcp:127.0.0.1:" + std::to_string(pair.listener.port()));
  EXPECT_EQ(pair.listener.address(), pair.driver->describe());
  const Bytes command = {0xFA, 0xFB, 0x06, 0x04, 0x3B, 0x01, 0x00, 0x05, 0x3B};
  pair.driver->write_all(command, deadline_in(kPatience));
  EXPECT_EQ(read_exactly(*pair.device, command.size()), command);
  const Bytes reply = {0xFA, 0xFB, 0x03, 0x01, 0x00, 0x01};
  pair.device->write_all(reply, deadline_in(kPatience));
  EXPECT_EQ(read_exactly(*pair.driver, reply.size()), reply);
  EXPECT_EQ(pair.driver->counters().snapshot().bytes_out, command.size());
  EXPECT_EQ(pair.driver->counters().snapshot().bytes_in, reply.size());
}

TEST(TcpLink, OneThreadReadsWhileAnotherWritesAndTraces) {
  Connected pair;
  constexpr std::size_t kTotal = 64 * 1024;
  std::atomic<std::size_t> traced_in{0};
  Bytes echoed;
  std::thread reader([&] { echoed = read_exactly(*pair.driver, kTotal); });
  const Bytes chunk(1024, 0x5A);
  for (std::size_t sent = 0; sent < kTotal; sent += chunk.size()) {
    if (sent == kTotal / 2) {
      pair.driver->set_trace_hook([&](Direction direction, std::span<const std::uint8_t> bytes, LinkClock::time_point) {
        if (direction == Direction::in) traced_in += bytes.size();
      });
    }
    pair.device->write_all(chunk, deadline_in(kPatience));
    pair.driver->write_all(std::span(chunk).first(1), deadline_in(kPatience));
  }
  reader.join();
  EXPECT_EQ(echoed.size(), kTotal);
  EXPECT_LE(traced_in.load(), kTotal);
  EXPECT_EQ(pair.driver->counters().snapshot().bytes_in, kTotal);
  EXPECT_EQ(pair.driver->counters().snapshot().bytes_out, kTotal / chunk.size());
}

TEST(TcpLink, HasNoLineSpeed) {
  Connected pair;
  EXPECT_FALSE(pair.driver->set_baud(38400));
  EXPECT_EQ(pair.driver->baud(), 0);
  pair.driver->drain();
}

TEST(TcpLink, ReadTimesOutAtTheDeadline) {
  Connected pair;
  std::uint8_t buffer[4];
  const Deadline deadline = deadline_in(30ms);
  EXPECT_EQ(pair.driver->read_some(buffer, deadline), 0u);
  EXPECT_GE(LinkClock::now(), deadline);
}

TEST(TcpLink, PeerClosingReadsAsDisconnected) {
  Connected pair;
  const Bytes last = {0x01, 0x02};
  pair.device->write_all(last, deadline_in(kPatience));
  pair.device.reset();
  // Bytes sent before the close still arrive; then the close is an error.
  EXPECT_EQ(read_exactly(*pair.driver, last.size()), last);
  std::uint8_t buffer[4];
  try {
    pair.driver->read_some(buffer, deadline_in(kPatience));
    FAIL() << "read past the peer's close";
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::disconnected);
    EXPECT_TRUE(contains(error.what(), pair.driver->describe() + ": the peer closed the connection")) << error.what();
  }
}

TEST(TcpLink, WritingToAVanishedPeerFailsWithoutSigpipe) {
  Connected pair;
  pair.device.reset();
  const Bytes chunk(1024, 0x55);
  bool failed = false;
  // The first writes may be accepted before the reset comes back.
  for (int attempt = 0; attempt < 100 && !failed; ++attempt) {
    try {
      pair.driver->write_all(chunk, deadline_in(kPatience));
      std::uint8_t buffer[1];
      (void)pair.driver->read_some(buffer, deadline_in(5ms));
    } catch (const LinkError& error) {
      EXPECT_EQ(error.kind(), LinkErrorKind::disconnected) << error.what();
      failed = true;
    }
  }
  EXPECT_TRUE(failed);
}

TEST(TcpLink, ReopenReconnects) {
  Connected pair;
  pair.device.reset();
  pair.driver->reopen(deadline_in(kPatience));
  auto device = pair.listener.accept(deadline_in(kPatience));
  ASSERT_NE(device, nullptr);
  const Bytes hello = {0x42};
  pair.driver->write_all(hello, deadline_in(kPatience));
  EXPECT_EQ(read_exactly(*device, 1), hello);
  EXPECT_EQ(pair.driver->counters().snapshot().reconnects, 1u);
  // An accepted connection has nothing to dial.
  EXPECT_THROW(device->reopen(deadline_in(kPatience)), LinkError);
}

TEST(TcpLink, FlushInputDropsWhatArrived) {
  Connected pair;
  const Bytes stale = {1, 2, 3, 4};
  pair.device->write_all(stale, deadline_in(kPatience));
  ASSERT_NE(wait_for_fd(pair.driver->native_handle(), POLLIN, deadline_in(kPatience)), 0);
  pair.driver->flush_input();
  std::uint8_t buffer[4];
  EXPECT_EQ(pair.driver->read_some(buffer, LinkClock::now()), 0u);
  EXPECT_EQ(pair.driver->counters().snapshot().bytes_dropped, stale.size());
}

TEST(TcpLink, RefusedConnectionSaysSo) {
  std::uint16_t port = 0;
  {
    TcpListener closed_again("127.0.0.1", 0);
    port = closed_again.port();
  }
  const LinkError error = connect_error("127.0.0.1", port, deadline_in(kPatience));
  EXPECT_EQ(error.kind(), LinkErrorKind::connect_failed);
  EXPECT_EQ(error.port(), "tcp:127.0.0.1:" + std::to_string(port));
  EXPECT_TRUE(contains(error.what(), "connection refused")) << error.what();
}

TEST(TcpLink, ConnectGivesUpAtTheDeadline) {
  // A listener that never accepts, its backlog filled: further SYNs are
  // dropped, so a connect can only time out.
  UniqueFd server(::socket(AF_INET, SOCK_STREAM, 0));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(server.get(), reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(::listen(server.get(), 0), 0);
  socklen_t length = sizeof address;
  ASSERT_EQ(::getsockname(server.get(), reinterpret_cast<sockaddr*>(&address), &length), 0);
  const std::uint16_t port = ntohs(address.sin_port);
  std::vector<std::unique_ptr<TcpLink>> fillers;
  for (int i = 0; i < 8; ++i) {
    try {
      fillers.push_back(TcpLink::connect("127.0.0.1", port, deadline_in(100ms)));
    } catch (const LinkError& error) {
      // The backlog is full: this is the behaviour under test.
      EXPECT_EQ(error.kind(), LinkErrorKind::connect_failed);
      EXPECT_TRUE(contains(error.what(), "timed out")) << error.what();
      return;
    }
  }
  GTEST_SKIP() << "this kernel accepted every connection into the backlog";
}

TEST(TcpLink, HostNamesResolveAndEveryAddressIsTried) {
  // "localhost" may resolve to ::1 first, where nobody listens.
  TcpListener listener("127.0.0.1", 0);
  auto driver = TcpLink::connect("localhost", listener.port(), deadline_in(kPatience));
  EXPECT_EQ(driver->describe(), "tcp:localhost:" + std::to_string(listener.port()));
  EXPECT_NE(listener.accept(deadline_in(kPatience)), nullptr);
}

TEST(TcpLink, Ipv6Loopback) {
  std::unique_ptr<TcpListener> listener;
  try {
    listener = std::make_unique<TcpListener>("::1", 0);
  } catch (const LinkError&) {
    GTEST_SKIP() << "no IPv6 loopback here";
  }
  auto driver = TcpLink::connect("::1", listener->port(), deadline_in(kPatience));
  EXPECT_EQ(driver->describe(), "tcp:[::1]:" + std::to_string(listener->port()));
  auto device = listener->accept(deadline_in(kPatience));
  ASSERT_NE(device, nullptr);
  const Bytes hello = {0x06};
  device->write_all(hello, deadline_in(kPatience));
  EXPECT_EQ(read_exactly(*driver, 1), hello);
}

TEST(TcpLink, AdoptedBlockingSocketStillHonoursDeadlines) {
  TcpListener listener("127.0.0.1", 0);
  UniqueFd client(::socket(AF_INET, SOCK_STREAM, 0));  // blocking
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(listener.port());
  ASSERT_EQ(::connect(client.get(), reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  auto link = TcpLink::adopt(std::move(client), "client");
  auto device = listener.accept(deadline_in(kPatience));
  ASSERT_NE(device, nullptr);
  std::uint8_t buffer[1];
  EXPECT_EQ(link->read_some(buffer, deadline_in(10ms)), 0u);  // would hang if still blocking
  EXPECT_EQ(link->describe(), "client");
}

TEST(TcpListener, AcceptTimesOut) {
  TcpListener listener("127.0.0.1", 0);
  EXPECT_EQ(listener.accept(deadline_in(20ms)), nullptr);
  EXPECT_THROW(TcpListener("not-an-address", 0), LinkError);
}

}  // namespace tcp_link_test
}  // namespace playerkit::links
