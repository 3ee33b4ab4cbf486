#include "server/client_session.hpp"

#include <algorithm>

#include <boost/asio/buffer.hpp>
#include <boost/asio/post.hpp>

#include "protocol/banner.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"
#include "protocol/messages/player.hpp"
#include "protocol/messages/position.hpp"
#include "server/data_round.hpp"
#include "server/player_requests.hpp"

namespace playerkit::server {

namespace asio = boost::asio;
using protocol::MessageType;

namespace {

// 1.5 compared at most 31 characters of key.
std::string truncated_key(const std::string& key) { return key.substr(0, protocol::kKeyLength - 1); }

// The key of an AUTH payload: bytes 2.., NUL-terminated within 32 bytes.
std::string key_of(std::span<const std::uint8_t> payload) {
  std::array<char, protocol::kKeyLength> key{};
  const std::size_t n = std::min(payload.size() - 2, key.size() - 1);
  std::copy_n(payload.begin() + 2, n, key.begin());
  return std::string(key.data());
}

}  // namespace

ClientSession::ClientSession(Socket socket, core::ClientId id, std::uint16_t port,
                             SessionContext context)
    : socket_(std::move(socket)), context_(std::move(context)) {
  state_.id = id;
  state_.port = port;
  state_.auth_pending = context_.options.auth_key.has_value();
  boost::system::error_code ec;
  const auto endpoint = socket_.remote_endpoint(ec);
  peer_ = ec ? "unknown peer" : endpoint.address().to_string() + ":" + std::to_string(endpoint.port());
  socket_.set_option(asio::ip::tcp::no_delay(true), ec);
  // write_more() writes in place and waits only when the socket is full.
  socket_.non_blocking(true, ec);
}

std::string ClientSession::label() const { return "client " + std::to_string(state_.id) + " (" + peer_ + ")"; }

void ClientSession::start() {
  context_.logger.info(label() + " connected on port " + std::to_string(state_.port));
  // Clients read the banner with a single recv(): it goes first, in one write.
  const auto banner = protocol::make_banner();
  enqueue({banner.begin(), banner.end()});
  reschedule_pushes();
  read_more();
}

// ---------------------------------------------------------------- reading

void ClientSession::read_more() {
  if (closed_ || reading_ || awaiting_setup_) return;
  reading_ = true;
  socket_.async_read_some(asio::buffer(read_buffer_),
                          [self = shared_from_this()](const boost::system::error_code& ec,
                                                      std::size_t n) {
                            self->reading_ = false;
                            if (self->closed_) return;
                            if (ec) {
                              self->close(ec == asio::error::eof ? "disconnected"
                                                                 : "connection lost: " + ec.message());
                              return;
                            }
                            for (protocol::FrameEvent& event : self->reader_.feed(
                                     std::span<const std::uint8_t>(self->read_buffer_.data(), n))) {
                              self->incoming_.push_back(std::move(event));
                            }
                            self->handle_incoming();
                            self->read_more();
                          });
}

void ClientSession::handle_incoming() {
  while (!closed_ && !awaiting_setup_ && !incoming_.empty()) {
    const protocol::FrameEvent event = std::move(incoming_.front());
    incoming_.pop_front();
    handle_event(event);
  }
}

void ClientSession::handle_event(const protocol::FrameEvent& event) {
  if (const auto* message = std::get_if<protocol::Message>(&event)) {
    handle_message(*message);
  } else if (const auto* skipped = std::get_if<protocol::SkippedBytes>(&event)) {
    warn_once("garbage", label() + ": skipped " + std::to_string(skipped->count) +
                             " bytes that were not a message");
  } else {
    handle_oversize(std::get<protocol::OversizeMessage>(event).header);
  }
}

void ClientSession::handle_message(const protocol::Message& message) {
  if (state_.auth_pending) {
    handle_authentication(message);
    return;
  }
  switch (message.type()) {
    case MessageType::kRequest: handle_request(message); break;
    case MessageType::kCommand: handle_command(message); break;
    default:
      warn_once("type" + std::to_string(message.header.type),
                label() + ": ignored a message of type " + std::to_string(message.header.type) +
                    " (clients send only commands and requests)");
  }
}

void ClientSession::handle_authentication(const protocol::Message& message) {
  const auto& payload = message.payload;
  const bool accepted = message.header.device == protocol::kPlayerCode && payload.size() >= 2 &&
                        payload.size() <= protocol::AuthRequest::kWireSize &&
                        ((payload[0] << 8) | payload[1]) == protocol::kPlayerAuthReq &&
                        key_of(payload) == truncated_key(*context_.options.auth_key);
  if (!accepted) {
    close("authentication failed");
    return;
  }
  state_.auth_pending = false;
  send_reply(MessageType::kAck, message.device(), {});
  reschedule_pushes();
}

void ClientSession::handle_request(const protocol::Message& message) {
  if (message.header.device != protocol::kPlayerCode) {
    handle_device_request(message);
    return;
  }
  if (const std::optional<PlayerReply> reply = answer_or_set_up_first(message)) {
    send_reply(reply->type, message.device(), reply->payload);
    if (reply->schedule_changed) reschedule_pushes();
    if (reply->round_requested) request_round();
  }
}

std::optional<PlayerReply> ClientSession::answer_or_set_up_first(const protocol::Message& message) {
  if (context_.set_up_in_background) {
    const SetupFirst first = device_to_set_up_first(state_, message.payload, context_.devices);
    if (first.device != nullptr) {
      awaiting_setup_ = true;
      context_.set_up_in_background(
          *first.device, [self = shared_from_this(), message, first](bool subscribed) {
            self->finish_device_open(message, *first.device, first.is_source, subscribed);
          });
      return std::nullopt;
    }
  }
  return answer_player_request(state_, message.payload, context_.devices);
}

void ClientSession::finish_device_open(const protocol::Message& request, core::Device& device,
                                       bool is_source, bool subscribed) {
  awaiting_setup_ = false;
  if (subscribed) held_for_open_.push_back(&device);
  std::optional<PlayerReply> reply;
  if (!closed_) {
    if (!is_source || !subscribed) {
      // The device asked for is up (or refused), or a source of it refused:
      // then the client gets 'e' without a second, blocking, attempt.
      reply = answer_device_request_after_setup(state_, request.payload, context_.devices, subscribed);
    } else {
      // A source is up: the next one, or the device itself, which now sets
      // up on the event loop without waiting (its sources are running).
      reply = answer_or_set_up_first(request);
      if (awaiting_setup_) return;
    }
  }
  // The setups' own subscriptions: the client holds its own by now (or none),
  // and the counts are right by the time the client reads its answer.
  for (core::Device* held : held_for_open_) held->unsubscribe_from_event_loop();
  held_for_open_.clear();
  if (reply) send_reply(reply->type, request.device(), reply->payload);
  handle_incoming();
  read_more();
}

void ClientSession::handle_device_request(const protocol::Message& message) {
  const protocol::DeviceAddress address = message.device();
  const auto now = context_.clock.now();
  const Access access = state_.subscriptions.access(address);
  core::Device* device = context_.devices.find(state_.port, address);
  if (device == nullptr || !(SubscriptionTable::can_read(access) || SubscriptionTable::can_write(access))) {
    send_reply(MessageType::kError, address, {});
    return;
  }
  // 1.5 silently dropped empty requests and cut long ones to 4096 bytes; an
  // answer is better than a client waiting for one.
  if (message.payload.empty() || message.payload.size() > protocol::kMaxRequestReplySize) {
    warn_once("request-size", label() + ": request of " + std::to_string(message.payload.size()) +
                                  " bytes to " + device->name() + " refused");
    send_reply(MessageType::kNack, address, {});
    return;
  }
  if (device->enqueue_request({state_.id, address, message.payload, now}) ==
      core::Device::RequestStatus::kQueueFull) {
    send_reply(MessageType::kError, address, {});
    return;
  }
  // Event-loop drivers answer right away, from this thread; threaded drivers
  // answer from theirs. Either way the reply comes back through the server.
  if (!device->driver().runs_own_thread()) device->service_requests();
}

void ClientSession::handle_command(const protocol::Message& message) {
  const protocol::DeviceAddress address = message.device();
  const std::string target = protocol::to_string(address);
  core::Device* device = context_.devices.find(state_.port, address);
  if (device == nullptr) {
    warn_once("cmd-nodev" + target, label() + ": command to " + target + ", which is not served here");
    return;
  }
  if (!SubscriptionTable::can_write(state_.subscriptions.access(address))) {
    warn_once("cmd-access" + target,
              label() + ": command to " + target + " ignored: the client has no write access");
    return;
  }
  switch (device->put_command(state_.id, message.payload)) {
    case core::Device::CommandStatus::kAccepted: break;
    case core::Device::CommandStatus::kReadOnly:
      warn_once("cmd-readonly" + target,
                label() + ": command to " + device->name() + " ignored: it takes no commands");
      break;
    case core::Device::CommandStatus::kWrongSize:
      warn_once("cmd-size" + target, label() + ": command of " +
                                         std::to_string(message.payload.size()) + " bytes to " +
                                         device->name() + " ignored: wrong size for its interface");
      break;
  }
}

void ClientSession::handle_oversize(const protocol::MessageHeader& header) {
  if (state_.auth_pending) {  // any first message but a good AUTH ends the connection
    close("authentication failed (oversize first message)");
    return;
  }
  warn_once("oversize", label() + ": dropped a message of " + std::to_string(header.size) +
                            " bytes (the limit is " + std::to_string(protocol::kMaxPayloadSize) + ")");
  if (header.type == static_cast<std::uint16_t>(MessageType::kRequest)) {
    send_reply(MessageType::kNack, {header.device, header.device_index}, {});
  }
}

// ---------------------------------------------------------------- writing

void ClientSession::deliver_reply(const core::Reply& reply) {
  if (closed_) return;
  if (reply.payload.size() > protocol::kMaxRequestReplySize) {
    context_.logger.error(label() + ": a driver's reply of " + std::to_string(reply.payload.size()) +
                          " bytes is too long for clients; sending NACK instead");
    send_reply(MessageType::kNack, reply.device, {}, reply.timestamp);
    return;
  }
  send_reply(reply.type, reply.device, reply.payload, reply.timestamp);
}

void ClientSession::send_reply(MessageType type, protocol::DeviceAddress device,
                               std::span<const std::uint8_t> payload,
                               std::optional<protocol::Timestamp> produced) {
  const auto now = context_.clock.now();
  auto header = protocol::make_header(type, device, now, produced.value_or(now));
  enqueue(protocol::encode_message(header, payload));
  if (output_bytes_ > context_.options.max_pending_reply_bytes) {
    close("does not read its replies (" + std::to_string(output_bytes_) + " bytes waiting)");
  }
}

void ClientSession::enqueue(std::vector<std::uint8_t> bytes) {
  if (closed_) return;
  output_bytes_ += bytes.size();
  output_.push_back(std::move(bytes));
  write_more();
}

void ClientSession::request_round() {
  if (closed_ || state_.auth_pending) return;
  if (round_pending_) ++stats_.rounds_dropped;
  round_pending_ = true;
  write_more();
}

void ClientSession::write_more() {
  if (closed_ || waiting_for_room_) return;
  // Written in place while the socket takes them (almost always, at once):
  // an asynchronous write per round would cost a queued operation and a
  // completion handler each, a few per cent of the loop at 1000 clients.
  for (;;) {
    if (output_.empty() && round_pending_) {
      round_pending_ = false;
      if (state_.push_mode() || std::exchange(state_.data_requested, false)) {
        DataRound round = build_data_round(state_, context_.devices, context_.clock.now(),
                                           std::move(spare_bytes_));
        ++stats_.rounds_sent;
        output_bytes_ += round.bytes.size();
        output_.push_back(std::move(round.bytes));
      }
    }
    if (output_.empty()) return;

    // One gathered write of up to 64 queued vectors.
    std::array<asio::const_buffer, 64> buffers;
    std::size_t count = 0;
    for (const auto& bytes : output_) {
      if (count == buffers.size()) break;
      const std::size_t skip = count == 0 ? front_offset_ : 0;
      buffers[count++] = asio::const_buffer(bytes.data() + skip, bytes.size() - skip);
    }
    boost::system::error_code ec;
    const std::size_t written = socket_.write_some(std::span<const asio::const_buffer>(buffers.data(), count), ec);
    if (ec == asio::error::would_block || ec == asio::error::try_again || (!ec && written == 0)) {
      wait_for_room();
      return;
    }
    if (ec) {
      close("connection lost: " + ec.message());
      return;
    }
    consume_written(written);
  }
}

void ClientSession::wait_for_room() {
  waiting_for_room_ = true;
  last_write_progress_ = Clock::now();
  socket_.async_wait(Socket::wait_write, [self = shared_from_this()](const boost::system::error_code& ec) {
    self->waiting_for_room_ = false;
    if (self->closed_) return;
    if (ec) {
      self->close("connection lost: " + ec.message());
      return;
    }
    self->last_write_progress_ = Clock::now();
    self->write_more();
  });
}

void ClientSession::consume_written(std::size_t written) {
  output_bytes_ -= written;
  while (written > 0) {
    const std::size_t left_in_front = output_.front().size() - front_offset_;
    if (written < left_in_front) {
      front_offset_ += written;
      break;
    }
    written -= left_in_front;
    keep_as_spare(std::move(output_.front()));
    output_.pop_front();
    front_offset_ = 0;
  }
}

void ClientSession::keep_as_spare(std::vector<std::uint8_t> written) {
  // One vector is enough (a session builds one round at a time); a huge one,
  // from a burst of replies, is given back rather than held for good.
  constexpr std::size_t kLargestSpare = 64 * 1024;
  if (spare_bytes_.capacity() == 0 && written.capacity() <= kLargestSpare) {
    spare_bytes_ = std::move(written);
  }
}

void ClientSession::check_stalled(std::chrono::steady_clock::time_point now) {
  if (closed_ || !waiting_for_room_) return;
  if (now - last_write_progress_ > context_.options.stall_timeout) {
    const auto seconds = std::chrono::duration<double>(now - last_write_progress_).count();
    context_.logger.warning(label() + ": has not read anything for " + std::to_string(seconds).substr(0, 4) +
                            " s; disconnecting it (" + std::to_string(stats_.rounds_dropped) +
                            " data rounds dropped)");
    close("stalled");
  }
}

// ---------------------------------------------------------------- schedule

void ClientSession::reschedule_pushes() {
  ++push_generation_;
  if (closed_ || state_.auth_pending || !state_.push_mode() || state_.frequency == 0) return;
  // As in 1.5, a round is due once a period has passed since the last one; a
  // new client has had none, so its first round goes out at once.
  next_push_ = last_push_ == Clock::time_point{} ? Clock::now() : last_push_ + push_period();
  context_.push_schedule.add(next_push_, weak_from_this(), push_generation_);
}

void ClientSession::push_due(std::uint64_t generation) {
  if (closed_ || generation != push_generation_) return;
  const auto now = Clock::now();
  last_push_ = now;
  request_round();
  if (closed_) return;
  const auto period = push_period();
  // Keep the cadence and its phase: after a hiccup longer than a period,
  // skip the missed slots rather than restart from now. Restarting would
  // line up every client delayed by the same hiccup, and their rounds would
  // go out in bursts from then on.
  next_push_ += period;
  if (next_push_ <= now) next_push_ += period * ((now - next_push_) / period + 1);
  context_.push_schedule.add(next_push_, weak_from_this(), generation);
}

ClientSession::Clock::duration ClientSession::push_period() const {
  const unsigned hz = std::min<unsigned>(state_.frequency, context_.options.max_push_frequency);
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / hz));
}

// ---------------------------------------------------------------- ending

void ClientSession::release_devices() {
  for (const SubscriptionTable::Entry& entry : state_.subscriptions.entries()) {
    core::Device* device = context_.devices.find(state_.port, entry.device);
    const int held = SubscriptionTable::held_subscriptions(entry.access);
    if (device == nullptr || held == 0) continue;
    if (SubscriptionTable::can_read(entry.access)) device->readers().forget(state_.id);
    // A robot whose last client vanished must not drive on with the last
    // command: stop it, as 1.5 did (1.5 stopped position:0 whichever position
    // device it was, and left the state/type bytes uninitialised).
    if (entry.device.interface == protocol::kPositionCode && device->subscriptions() == held) {
      const auto stop = protocol::encode(protocol::PositionCommand{});
      device->put_command(state_.id, stop);
    }
    for (int i = 0; i < held; ++i) device->unsubscribe_from_event_loop();
  }
  state_.subscriptions.entries().clear();
}

void ClientSession::close(const std::string& reason) {
  if (closed_) return;
  closed_ = true;
  ++push_generation_;
  boost::system::error_code ignored;
  socket_.shutdown(Socket::shutdown_both, ignored);
  socket_.close(ignored);
  release_devices();
  output_.clear();
  context_.logger.info(label() + " " + reason);
  if (context_.closed) context_.closed(state_.id);
}

void ClientSession::warn_once(const std::string& kind, const std::string& message) {
  if (warned_.insert(kind).second) {
    context_.logger.warning(message);
  } else {
    context_.logger.debug(message);
  }
}

}  // namespace playerkit::server
