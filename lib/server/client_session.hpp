#pragma once
// One client connection: reads messages and answers them, sends data rounds
// on the client's schedule, and never lets a slow reader hold anyone else up.
//
// Output is a queue of replies plus at most one data round waiting: when a
// round falls due while the socket is still busy, it is only marked pending
// and built (with the freshest data) once the socket has room. Rounds that
// fall due meanwhile are dropped, so a slow client sees lower-rate but current
// data, and its output never grows without bound. Replies are never dropped.
//
// A DEV request whose device must first be set up off the event loop (its
// driver's setup may block) is answered when that setup ends; meanwhile the
// client's later messages wait, unread, so that every reply keeps its place.
// The other clients are not held up, nor this client's data rounds.
//
// Everything here runs on the server's event-loop thread.

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <boost/asio/ip/tcp.hpp>

#include "core/clock.hpp"
#include "core/device_table.hpp"
#include "core/logger.hpp"
#include "protocol/frame_reader.hpp"
#include "server/client_state.hpp"
#include "server/player_requests.hpp"
#include "server/push_schedule.hpp"
#include "server/server_options.hpp"

namespace playerkit::server {

// What a session needs from the server that owns it.
struct SessionContext {
  core::DeviceTable& devices;
  const core::Clock& clock;
  core::Logger& logger;
  const ServerOptions& options;
  PushSchedule& push_schedule;  // when this client's data rounds fall due
  std::function<void(core::ClientId)> closed;  // called once, when the session ends
  // Subscribes to a device whose setup may block on a thread of its own, then
  // calls `done(subscribed)` on the event loop (BackgroundSetups). Empty:
  // such setups run in place, holding the loop up.
  std::function<void(core::Device&, std::function<void(bool subscribed)> done)> set_up_in_background;
};

struct SessionStats {
  std::uint64_t rounds_sent = 0;
  std::uint64_t rounds_dropped = 0;  // fell due while the client was still busy
};

class ClientSession final : public std::enable_shared_from_this<ClientSession>, public PushTarget {
 public:
  using Socket = boost::asio::ip::tcp::socket;

  ClientSession(Socket socket, core::ClientId id, std::uint16_t port, SessionContext context);

  void start();
  void deliver_reply(const core::Reply& reply);
  // Ends the session: releases its devices and closes the socket.
  void close(const std::string& reason);
  // Closes the session if its socket has taken nothing for the stall timeout.
  void check_stalled(std::chrono::steady_clock::time_point now);
  // A push-mode round has fallen due (called by the PushSchedule).
  void push_due(std::uint64_t generation) override;

  [[nodiscard]] core::ClientId id() const { return state_.id; }
  [[nodiscard]] const SessionStats& stats() const { return stats_; }

 private:
  using Clock = std::chrono::steady_clock;

  void read_more();
  // Handles the messages read, in order, until one has to wait for a setup.
  void handle_incoming();
  void handle_event(const protocol::FrameEvent& event);
  void handle_message(const protocol::Message& message);
  void handle_authentication(const protocol::Message& message);
  void handle_request(const protocol::Message& message);
  // The answer to a request to the `player` device, or nullopt when a DEV
  // request first waits for a setup off the event loop (finish_device_open
  // comes back to it).
  std::optional<PlayerReply> answer_or_set_up_first(const protocol::Message& message);
  // `device` (the one asked for, or one of its sources) was set up elsewhere.
  void finish_device_open(const protocol::Message& request, core::Device& device, bool is_source,
                          bool subscribed);
  void handle_device_request(const protocol::Message& message);
  void handle_command(const protocol::Message& message);
  void handle_oversize(const protocol::MessageHeader& header);

  // Header time is now; timestamp is when a driver produced the reply, or now
  // for the server's own answers.
  void send_reply(protocol::MessageType type, protocol::DeviceAddress device,
                  std::span<const std::uint8_t> payload,
                  std::optional<protocol::Timestamp> produced = std::nullopt);
  void enqueue(std::vector<std::uint8_t> bytes);
  void request_round();
  void write_more();
  void wait_for_room();
  void consume_written(std::size_t written);
  // Keeps a written-out byte vector to build the next round in.
  void keep_as_spare(std::vector<std::uint8_t> written);

  // Starts the push schedule afresh after a change of mode or frequency.
  void reschedule_pushes();
  [[nodiscard]] Clock::duration push_period() const;
  void release_devices();
  // Logs a problem once per kind per connection, then only at debug level,
  // so that a misbehaving client cannot flood the log.
  void warn_once(const std::string& kind, const std::string& message);
  [[nodiscard]] std::string label() const;

  Socket socket_;
  SessionContext context_;
  ClientState state_;
  std::string peer_;
  bool closed_ = false;

  protocol::FrameReader reader_;
  std::array<std::uint8_t, 16384> read_buffer_{};
  bool reading_ = false;
  // Read but not handled yet: at most one read's worth, since reading stops
  // while a DEV request waits for its device's setup.
  std::deque<protocol::FrameEvent> incoming_;
  bool awaiting_setup_ = false;
  // Devices a DEV request had set up off the event loop (it, or its sources
  // one after the other), each held by its setup's subscription until the
  // request is answered.
  std::vector<core::Device*> held_for_open_;

  std::deque<std::vector<std::uint8_t>> output_;
  std::size_t output_bytes_ = 0;
  std::size_t front_offset_ = 0;  // bytes of output_.front() already written
  std::vector<std::uint8_t> spare_bytes_;
  bool waiting_for_room_ = false;  // the socket was full; a wait for room is pending
  bool round_pending_ = false;
  Clock::time_point last_write_progress_;

  std::uint64_t push_generation_ = 0;  // entries of older generations are stale
  Clock::time_point last_push_{};
  Clock::time_point next_push_{};

  std::set<std::string> warned_;
  SessionStats stats_;
};

}  // namespace playerkit::server
