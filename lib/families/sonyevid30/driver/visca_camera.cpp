#include "families/sonyevid30/driver/visca_camera.hpp"

#include <utility>

namespace playerkit::drivers::sonyevid30 {

using visca::Reply;

ViscaCamera::ViscaCamera(links::ByteLink& link, std::function<bool()> stopping,
                         std::function<void(const std::string&)> warn)
    : format_(visca::reply_packet_options()),
      reader_(link, format_, visca::reply_packet_options().max_length),
      exchanger_(reader_, std::move(stopping), "the camera"),
      warn_(std::move(warn)) {}

bool ViscaCamera::note(const Reply& reply) {
  const bool socket_known = reply.socket == 1 || reply.socket == 2;
  if (reply.kind == Reply::Kind::completion && socket_known) {
    sockets_[reply.socket - 1].reset();
    ++completions_;
    return true;
  }
  // An error naming a socket we ran a command in: that command failed after its ACK.
  if (reply.kind == Reply::Kind::error && socket_known && busy(reply.socket) && reply.error_code != visca::kCancelled &&
      reply.error_code != visca::kNoSocket) {
    sockets_[reply.socket - 1].reset();
    ++late_errors_;
    if (warn_) warn_("the camera could not finish the command in socket " + std::to_string(reply.socket) + ": " +
                     visca::error_text(reply.error_code));
    return true;
  }
  return false;
}

void ViscaCamera::take_pending() {
  while (auto telegram = exchanger_.next(links::LinkClock::now())) {
    const Reply reply = visca::parse_reply(*telegram);
    if (note(reply) || reply.kind != Reply::Kind::error) continue;
    ++late_errors_;
    if (warn_) warn_("the camera sent an error no command was waiting for: " + visca::error_text(reply.error_code));
  }
}

int ViscaCamera::send_command(const visca::Bytes& packet, const std::string& name, Function function) {
  take_pending();
  int socket = 0;
  const links::ExchangeOutcome outcome = exchanger_.try_exchange(
      {.name = name,
       .bytes = packet,
       .matcher =
           [&](std::span<const std::uint8_t> telegram) {
             const Reply reply = visca::parse_reply(telegram);
             if (reply.kind == Reply::Kind::ack && (reply.socket == 1 || reply.socket == 2)) {
               socket = reply.socket;
               return links::ReplyMatch::mine;
             }
             if (note(reply)) return links::ReplyMatch::not_mine;
             const bool cancel_reply =
                 reply.error_code == visca::kCancelled || reply.error_code == visca::kNoSocket;
             return reply.kind == Reply::Kind::error && !cancel_reply ? links::ReplyMatch::refusal
                                                                      : links::ReplyMatch::not_mine;
           },
       .timeout = kReplyTimeout,
       // Sent again only when nothing came: every command here sets a state, so twice is as once.
       .attempts = kAttempts,
       .flush_first = false});
  if (outcome.replied()) {
    sockets_[socket - 1] = function;
    return socket;
  }
  if (outcome.failure == links::ExchangeFailure::refused) {
    const Reply refusal = visca::parse_reply(outcome.telegram);
    if (refusal.error_code == visca::kBufferFull) return -1;
    throw links::ExchangeError(links::ExchangeFailure::refused,
                               "the camera refused " + name + " (" + visca::hex(packet) +
                                   "): " + visca::error_text(refusal.error_code));
  }
  throw links::ExchangeError(*outcome.failure, outcome.message);
}

int ViscaCamera::command(const visca::Bytes& packet, const std::string& name, Function function) {
  const int socket = send_command(packet, name, function);
  if (socket > 0) return socket;
  // Both sockets busy: 1.5 cancelled both; the one this command would
  // replace is enough (the other command's motion goes on).
  int victim = 1;
  for (int s = 1; s <= 2; ++s) {
    if (function != Function::other && sockets_[s - 1] == function) victim = s;
  }
  cancel(victim);
  const int again = send_command(packet, name, function);
  if (again > 0) return again;
  throw links::ExchangeError(links::ExchangeFailure::refused, "the camera refused " + name + " (" +
                                                                   visca::hex(packet) + "): " +
                                                                   visca::error_text(visca::kBufferFull));
}

visca::Bytes ViscaCamera::inquire(const visca::Bytes& packet, const std::string& name,
                                  const std::function<bool(const Reply&)>& valid, std::chrono::milliseconds timeout) {
  take_pending();
  const links::ExchangeOutcome outcome = exchanger_.try_exchange(
      {.name = name,
       .bytes = packet,
       .matcher =
           [&](std::span<const std::uint8_t> telegram) {
             const Reply reply = visca::parse_reply(telegram);
             if (reply.kind == Reply::Kind::answer) {
               return valid(reply) ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
             }
             if (note(reply)) return links::ReplyMatch::not_mine;
             return reply.kind == Reply::Kind::error && reply.socket == 0 ? links::ReplyMatch::refusal
                                                                          : links::ReplyMatch::not_mine;
           },
       .timeout = timeout,
       .attempts = kAttempts,
       .flush_first = false});
  if (outcome.replied()) return outcome.telegram;
  if (outcome.failure == links::ExchangeFailure::refused) {
    throw links::ExchangeError(links::ExchangeFailure::refused,
                               "the camera refused " + name + " (" + visca::hex(packet) +
                                   "): " + visca::error_text(visca::parse_reply(outcome.telegram).error_code));
  }
  throw links::ExchangeError(*outcome.failure, outcome.message);
}

bool ViscaCamera::cancel(int socket) {
  take_pending();
  bool cancelled = false;
  const links::ExchangeOutcome outcome = exchanger_.try_exchange(
      {.name = "cancel socket " + std::to_string(socket),
       .bytes = visca::cancel(socket),
       .matcher =
           [&](std::span<const std::uint8_t> telegram) {
             const Reply reply = visca::parse_reply(telegram);
             if (reply.kind == Reply::Kind::error && reply.socket == socket &&
                 (reply.error_code == visca::kCancelled || reply.error_code == visca::kNoSocket)) {
               cancelled = reply.error_code == visca::kCancelled;
               return links::ReplyMatch::mine;
             }
             note(reply);
             return links::ReplyMatch::not_mine;
           },
       .timeout = kReplyTimeout,
       .attempts = kAttempts,
       .flush_first = false});
  if (!outcome.replied()) throw links::ExchangeError(*outcome.failure, outcome.message);
  sockets_[socket - 1].reset();
  if (cancelled) ++cancelled_;
  return cancelled;
}

}  // namespace playerkit::drivers::sonyevid30
