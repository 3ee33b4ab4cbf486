#include "page_server.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace playerkit::player_view {
namespace page_server_test {

// A plain TCP client on 127.0.0.1, every read bounded by a deadline.
class Connection {
 public:
  explicit Connection(std::uint16_t port) : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  }
  ~Connection() { ::close(fd_); }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  [[nodiscard]] bool connected() const { return connected_; }
  void send(const std::string& text) { ASSERT_EQ(::write(fd_, text.data(), text.size()), ssize_t(text.size())); }

  // Reads until `done(received)` or 10 s pass; returns what arrived.
  template <typename Done>
  std::string read_until(Done done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!done(buffer_) && std::chrono::steady_clock::now() < deadline) {
      pollfd ready{fd_, POLLIN, 0};
      if (::poll(&ready, 1, 100) <= 0) continue;
      char chunk[4096];
      const ssize_t n = ::read(fd_, chunk, sizeof chunk);
      if (n <= 0) break;
      buffer_.append(chunk, static_cast<std::size_t>(n));
    }
    return buffer_;
  }
  void consume(std::size_t n) { buffer_.erase(0, n); }

 private:
  int fd_;
  bool connected_ = false;
  std::string buffer_;
};

std::vector<PageAsset> assets() { return {{"/", "text/html; charset=utf-8", "<canvas></canvas>"}}; }

// An unmasked text frame from the server: its payload, once whole.
std::optional<std::string> text_frame(const std::string& bytes, std::size_t& length) {
  if (bytes.size() < 2) return std::nullopt;
  std::size_t size = static_cast<std::uint8_t>(bytes[1]) & 0x7f, header = 2;
  if (size == 126) {
    if (bytes.size() < 4) return std::nullopt;
    size = (std::size_t(std::uint8_t(bytes[2])) << 8) | std::uint8_t(bytes[3]);
    header = 4;
  } else if (size == 127) {
    if (bytes.size() < 10) return std::nullopt;
    size = 0;
    for (int i = 2; i < 10; ++i) size = (size << 8) | std::uint8_t(bytes[std::size_t(i)]);
    header = 10;
  }
  if (bytes.size() < header + size) return std::nullopt;
  length = header + size;
  return bytes.substr(header, size);
}

std::string next_frame(Connection& connection) {
  std::size_t length = 0;
  std::optional<std::string> frame;
  connection.read_until([&](const std::string& bytes) { return (frame = text_frame(bytes, length)).has_value(); });
  if (!frame) return "(no frame)";
  connection.consume(length);
  return *frame;
}

void open_websocket(Connection& connection) {
  connection.send(
      "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
      "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n");
  const auto reply = connection.read_until([](const std::string& bytes) { return bytes.find("\r\n\r\n") != std::string::npos; });
  ASSERT_EQ(reply.rfind("HTTP/1.1 101", 0), 0u) << reply;
  // RFC 6455's own example key and answer.
  EXPECT_NE(reply.find("s3pPLMBiTxaQ9kYGzzhZRbK+xOo="), std::string::npos) << reply;
  connection.consume(reply.find("\r\n\r\n") + 4);
}

TEST(PageServer, ServesThePageAndAnswers404Otherwise) {
  PageServer server("127.0.0.1", 0, assets());
  server.start();
  Connection page(server.port());
  ASSERT_TRUE(page.connected());
  page.send("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
  const auto reply = page.read_until([](const std::string& bytes) { return bytes.find("</canvas>") != std::string::npos; });
  EXPECT_EQ(reply.rfind("HTTP/1.1 200 OK", 0), 0u) << reply;
  EXPECT_NE(reply.find("Content-Type: text/html; charset=utf-8"), std::string::npos) << reply;

  Connection other(server.port());
  other.send("GET /nothing HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
  const auto missing = other.read_until([](const std::string& bytes) { return bytes.find("not found") != std::string::npos; });
  EXPECT_EQ(missing.rfind("HTTP/1.1 404", 0), 0u) << missing;
}

TEST(PageServer, APageGetsTheGreetingThenTheNewestFrame) {
  PageServer server("127.0.0.1", 0, assets());
  server.add_greeting("{\"type\":\"map\"}");
  server.publish("{\"frame\":1}");
  server.publish("{\"frame\":2}");
  server.start();
  Connection page(server.port());
  open_websocket(page);
  EXPECT_EQ(next_frame(page), "{\"type\":\"map\"}");
  // Frame 1 was replaced before the page opened: newest wins.
  EXPECT_EQ(next_frame(page), "{\"frame\":2}");
  server.publish("{\"frame\":3}");
  EXPECT_EQ(next_frame(page), "{\"frame\":3}");
}

TEST(PageServer, EveryOpenPageGetsEachFrame) {
  PageServer server("127.0.0.1", 0, assets());
  server.start();
  Connection first(server.port()), second(server.port());
  open_websocket(first);
  open_websocket(second);
  // Both are registered once each has had a frame published after it opened.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (server.pages() < 2 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(server.pages(), 2u);
  server.publish("{\"frame\":7}");
  EXPECT_EQ(next_frame(first), "{\"frame\":7}");
  EXPECT_EQ(next_frame(second), "{\"frame\":7}");
}

// A masked text frame, as a browser sends it.
std::string client_frame(const std::string& text) {
  std::string frame{char(0x81)};
  if (text.size() < 126) {
    frame += char(0x80 | text.size());
  } else {
    frame += {char(0x80 | 126), char(text.size() >> 8), char(text.size() & 0xff)};
  }
  const char mask[4] = {1, 2, 3, 4};
  frame.append(mask, 4);
  for (std::size_t i = 0; i < text.size(); ++i) frame += char(text[i] ^ mask[i % 4]);
  return frame;
}

TEST(PageServer, WhatPagesSayAndTheirClosingAreEvents) {
  PageServer server("127.0.0.1", 0, assets());
  server.start();
  {
    Connection page(server.port());
    open_websocket(page);
    page.send(client_frame("{\"type\":\"stop\"}"));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    std::vector<PageEvent> events;
    while (events.empty() && std::chrono::steady_clock::now() < deadline) {
      events = server.take_events();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].page, 1u);
    EXPECT_FALSE(events[0].closed);
    EXPECT_EQ(events[0].text, "{\"type\":\"stop\"}");
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  std::vector<PageEvent> events;
  while (events.empty() && std::chrono::steady_clock::now() < deadline) {
    events = server.take_events();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(events.size(), 1u);
  EXPECT_TRUE(events[0].closed);
  EXPECT_EQ(events[0].page, 1u);
}

TEST(PageServer, APageSendingTooMuchIsClosed) {
  PageServer server("127.0.0.1", 0, assets());
  server.start();
  Connection page(server.port());
  open_websocket(page);
  page.send(client_frame(std::string(5000, 'x')));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  std::vector<PageEvent> events;
  while (events.empty() && std::chrono::steady_clock::now() < deadline) {
    events = server.take_events();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(events.size(), 1u);
  EXPECT_TRUE(events[0].closed);
}

TEST(PageServer, APortInUseIsNamedWithTheReason) {
  PageServer first("127.0.0.1", 0, assets());
  try {
    PageServer second("127.0.0.1", first.port(), assets());
    FAIL() << "a second server listened on the same port";
  } catch (const PageServerError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot serve HTTP on 127.0.0.1:" + std::to_string(first.port()) + ": Address already in use");
  }
  EXPECT_THROW(PageServer("not-an-address", 0, assets()), PageServerError);
}

TEST(PageServer, TheEmbeddedPageHasItsCanvasAndScript) {
  const auto& embedded = page_assets();
  ASSERT_EQ(embedded.size(), 2u);
  EXPECT_EQ(embedded[0].path, "/");
  EXPECT_NE(embedded[0].body.find("<canvas id=\"view\">"), std::string_view::npos);
  EXPECT_EQ(embedded[1].path, "/view.js");
  EXPECT_NE(embedded[1].body.find("new WebSocket"), std::string_view::npos);
}

}  // namespace page_server_test
}  // namespace playerkit::player_view
