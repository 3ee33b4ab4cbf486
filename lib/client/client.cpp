#include "client/client.hpp"

#include <boost/asio/buffer.hpp>
#include <boost/asio/connect.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>

#include "protocol/banner.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/player.hpp"

namespace playerkit::client {

namespace asio = boost::asio;
using asio::ip::tcp;
using protocol::MessageType;
using Clock = std::chrono::steady_clock;

namespace {

std::vector<std::uint8_t> u16(std::uint16_t value) {
  return {static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value & 0xFF)};
}

constexpr protocol::DeviceAddress kPlayerDevice{protocol::kPlayerCode, 0};

}  // namespace

Client::Client()
    : io_(std::make_unique<asio::io_context>()),
      socket_(std::make_unique<tcp::socket>(*io_)),
      read_buffer_(64 * 1024) {}

Client::Client(Client&&) noexcept = default;
Client& Client::operator=(Client&&) noexcept = default;
Client::~Client() { close(); }

void Client::close() {
  if (!socket_) return;
  boost::system::error_code ignored;
  socket_->shutdown(tcp::socket::shutdown_both, ignored);
  socket_->close(ignored);
}

bool Client::run_until(const bool& done, Clock::time_point deadline) {
  io_->restart();
  while (!done) {
    const auto now = Clock::now();
    if (now >= deadline || io_->run_one_for(deadline - now) == 0) break;
  }
  if (done) return true;
  // Cancel and let the aborted handler run, so nothing refers to this call's
  // locals afterwards. It counts as a timeout even if the handler now runs.
  boost::system::error_code ignored;
  socket_->cancel(ignored);
  io_->restart();
  io_->run();
  return false;
}

Client Client::connect(const std::string& host, std::uint16_t port,
                       std::chrono::milliseconds timeout) {
  Client client;
  client.timeout_ = timeout;
  const auto deadline = Clock::now() + timeout;
  const std::string where = host + ":" + std::to_string(port);

  boost::system::error_code ec;
  tcp::resolver resolver(*client.io_);
  const auto endpoints = resolver.resolve(host, std::to_string(port), ec);
  if (ec) throw ClientError("cannot resolve " + where + ": " + ec.message());

  bool done = false;
  asio::async_connect(*client.socket_, endpoints,
                      [&](const boost::system::error_code& error, const tcp::endpoint&) {
                        ec = error;
                        done = true;
                      });
  if (!client.run_until(done, deadline)) throw TimeoutError("no connection to " + where + " within the timeout");
  if (ec) throw ClientError("cannot connect to " + where + ": " + ec.message());
  client.socket_->set_option(tcp::no_delay(true), ec);

  // The banner comes first, 32 bytes; nothing else starts like it.
  std::array<std::uint8_t, protocol::kBannerSize> banner{};
  done = false;
  asio::async_read(*client.socket_, asio::buffer(banner),
                   [&](const boost::system::error_code& error, std::size_t) {
                     ec = error;
                     done = true;
                   });
  if (!client.run_until(done, deadline)) throw TimeoutError(where + " sent no banner within the timeout");
  if (ec) throw ClientError(where + " closed the connection before its banner: " + ec.message());
  auto version = protocol::parse_banner(banner);
  if (!version) throw ClientError(where + " is not a Player server (no \"Player v.\" banner)");
  client.server_version_ = *version;
  return client;
}

void Client::feed(std::size_t received) {
  for (auto& event : reader_.feed(std::span<const std::uint8_t>(read_buffer_.data(), received))) {
    if (auto* message = std::get_if<protocol::Message>(&event)) {
      bool late_reply = false;
      if (protocol::is_reply(message->type())) {
        if (auto owed = abandoned_replies_.find(message->device()); owed != abandoned_replies_.end()) {
          // The answer to a request that timed out: never a later request's reply.
          late_reply = true;
          if (--owed->second == 0) abandoned_replies_.erase(owed);
        }
      }
      incoming_.push_back({std::move(*message), late_reply});
    } else {
      throw ClientError("the server sent bytes that are not a Player message");
    }
  }
}

bool Client::receive_more(Clock::time_point deadline) {
  const std::size_t before = incoming_.size();
  while (incoming_.size() == before) {
    bool done = false;
    boost::system::error_code ec;
    std::size_t received = 0;
    socket_->async_read_some(asio::buffer(read_buffer_),
                             [&](const boost::system::error_code& error, std::size_t n) {
                               ec = error;
                               received = n;
                               done = true;
                             });
    // Even on a timeout the read may have completed just before its cancel:
    // those bytes belong to the stream and are kept.
    run_until(done, deadline);
    if (ec == asio::error::operation_aborted) return false;
    if (ec == asio::error::eof) throw ClientError("the server closed the connection");
    if (ec) throw ClientError("connection lost: " + ec.message());
    feed(received);
    if (incoming_.size() == before && Clock::now() >= deadline) return false;
  }
  return true;
}

void Client::receive_available() {
  boost::system::error_code ec;
  socket_->non_blocking(true, ec);
  for (;;) {
    const std::size_t received = socket_->read_some(asio::buffer(read_buffer_), ec);
    if (ec == asio::error::would_block || ec == asio::error::try_again) break;
    if (ec == asio::error::eof) throw ClientError("the server closed the connection");
    if (ec) throw ClientError("connection lost: " + ec.message());
    feed(received);
  }
  socket_->non_blocking(false, ec);
}

void Client::async_read(ReadHandler handler) { handlers_.push_back(std::move(handler)); }

std::size_t Client::dispatch_handlers() {
  std::size_t ran = 0;
  while (!handlers_.empty() && !incoming_.empty()) {
    ReadHandler handler = std::move(handlers_.front());
    handlers_.pop_front();
    protocol::Message message = std::move(incoming_.front().message);
    incoming_.pop_front();
    handler(std::move(message));
    ++ran;
  }
  return ran;
}

std::size_t Client::poll() {
  if (!handlers_.empty()) receive_available();
  return dispatch_handlers();
}

std::size_t Client::run_for(std::chrono::milliseconds duration) {
  const auto deadline = Clock::now() + duration;
  std::size_t ran = dispatch_handlers();
  while (!handlers_.empty()) {
    if (!receive_more(deadline)) break;
    ran += dispatch_handlers();
  }
  return ran;
}

int Client::native_handle() {
  return socket_ && socket_->is_open() ? static_cast<int>(socket_->native_handle()) : -1;
}

std::optional<protocol::Message> Client::read(std::chrono::milliseconds timeout) {
  if (incoming_.empty() && !receive_more(Clock::now() + timeout)) return std::nullopt;
  protocol::Message message = std::move(incoming_.front().message);
  incoming_.pop_front();
  return message;
}

void Client::send(const std::vector<std::uint8_t>& bytes) {
  bool done = false;
  boost::system::error_code ec;
  asio::async_write(*socket_, asio::buffer(bytes), [&](const boost::system::error_code& error, std::size_t) {
    ec = error;
    done = true;
  });
  if (!run_until(done, Clock::now() + timeout_)) {
    // Part of the message may have gone out: the stream is no longer in step.
    close();
    throw TimeoutError("the server takes no data (connection closed)");
  }
  if (ec) throw ClientError("connection lost: " + ec.message());
}

void Client::write_command(protocol::DeviceAddress device, std::span<const std::uint8_t> payload) {
  send(protocol::encode_message(protocol::make_header(MessageType::kCommand, device, {}, {}), payload));
}

protocol::Message Client::request(protocol::DeviceAddress device, std::span<const std::uint8_t> payload) {
  const std::size_t queued_before = incoming_.size();
  send(protocol::encode_message(protocol::make_header(MessageType::kRequest, device, {}, {}), payload));
  const auto deadline = Clock::now() + timeout_;
  // Replies come in request order per device; messages already queued before
  // this request cannot be its reply.
  std::size_t next = queued_before;
  for (;;) {
    for (; next < incoming_.size(); ++next) {
      const auto& [message, late_reply] = incoming_[next];
      // A late reply stays queued for read(): it is not this request's answer.
      if (protocol::is_reply(message.type()) && message.device() == device && !late_reply) {
        protocol::Message reply = std::move(incoming_[next].message);
        incoming_.erase(incoming_.begin() + static_cast<std::ptrdiff_t>(next));
        return reply;
      }
    }
    if (!receive_more(deadline)) {
      ++abandoned_replies_[device];
      throw TimeoutError("no reply from " + protocol::to_string(device) + " within the timeout");
    }
  }
}

protocol::Message Client::player_request(std::vector<std::uint8_t> payload) {
  return request(kPlayerDevice, payload);
}

void Client::authenticate(std::string_view key) {
  protocol::AuthRequest auth;
  auth.subtype = protocol::kPlayerAuthReq;
  auth.auth_key.assign(key.substr(0, protocol::kKeyLength - 1));
  protocol::Message reply;
  try {
    reply = player_request(protocol::encode(auth));
  } catch (const TimeoutError&) {
    throw;
  } catch (const ClientError&) {
    // A 1.5 server answers a wrong key by hanging up.
    throw ClientError("authentication refused: the server closed the connection");
  }
  // A server without -k refuses AUTH with a NACK.
  if (reply.type() != MessageType::kAck) throw ClientError("authentication refused by the server");
}

AccessGrant Client::request_access(protocol::DeviceAddress device, protocol::Access access) {
  protocol::DeviceAccessRequest ask;
  ask.subtype = protocol::kPlayerDevReq;
  ask.code = device.interface;
  ask.index = device.index;
  ask.access = static_cast<std::uint8_t>(access);
  const auto reply = player_request(protocol::encode(ask));
  if (reply.type() != MessageType::kAck) {
    throw ClientError("the server refused the access request for " + protocol::to_string(device));
  }
  const auto granted = protocol::decode<protocol::DeviceAccessReply>(reply.payload);
  return {static_cast<protocol::Access>(granted.access), granted.driver_name.str()};
}

std::vector<DeviceEntry> Client::device_list() {
  const auto reply = player_request(u16(protocol::kPlayerDevlistReq));
  if (reply.type() != MessageType::kAck) throw ClientError("the server refused the device list");
  const auto list = protocol::decode<protocol::DeviceList>(reply.payload);
  std::vector<DeviceEntry> entries;
  for (std::size_t i = 0; i < list.device_count; ++i) {
    const auto& id = list.devices[i];
    protocol::DriverInfo ask;
    ask.subtype = protocol::kPlayerDriverinfoReq;
    ask.id = id;
    const auto info = player_request(protocol::encode(ask));
    std::string driver = info.type() == MessageType::kAck
                             ? protocol::decode<protocol::DriverInfo>(info.payload).driver_name.str()
                             : std::string();
    entries.push_back({{id.code, id.index}, id.port, std::move(driver)});
  }
  return entries;
}

void Client::set_data_mode(protocol::DataMode mode) {
  auto payload = u16(protocol::kPlayerDatamodeReq);
  payload.push_back(static_cast<std::uint8_t>(mode));
  if (player_request(payload).type() != MessageType::kAck) throw ClientError("data mode refused");
}

void Client::set_frequency(std::uint16_t hz) {
  auto payload = u16(protocol::kPlayerDatafreqReq);
  const auto value = u16(hz);
  payload.insert(payload.end(), value.begin(), value.end());
  if (player_request(payload).type() != MessageType::kAck) throw ClientError("data frequency refused");
}

void Client::request_data() {
  if (player_request(u16(protocol::kPlayerDataReq)).type() != MessageType::kAck) {
    throw ClientError("data request refused (the server is in a push mode)");
  }
}

}  // namespace playerkit::client
