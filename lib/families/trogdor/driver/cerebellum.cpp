#include "families/trogdor/driver/cerebellum.hpp"

#include "families/trogdor/protocol/trogdor_units.hpp"

#include <optional>
#include <stdexcept>
#include <string>

namespace playerkit::drivers::trogdor {

Cerebellum::Cerebellum(links::ByteLink& link, std::function<bool()> stopping)
    : reader_(link, format_, hw::kLongestReply), exchanger_(reader_, std::move(stopping), "the robot") {}

// A NACK is one byte any line noise can forge, so it does not end the
// wait: the robot's ACK may still follow it, and a message it really
// refused is sent again. Only NACKs and no ACK in every attempt is a refusal.
std::optional<hw::Bytes> Cerebellum::exchange(const char* name, const hw::Bytes& message, hw::ReplyShape shape,
                                              std::chrono::milliseconds timeout, int attempts) {
  format_.expect(shape);
  bool refused = false;
  const auto outcome = exchanger_.try_exchange({.name = name,
                                                .bytes = message,
                                                .matcher =
                                                    [&refused](std::span<const std::uint8_t> telegram) {
                                                      if (telegram[0] == hw::kAck) return links::ReplyMatch::mine;
                                                      refused = refused || telegram[0] == hw::kNack;
                                                      return links::ReplyMatch::not_mine;
                                                    },
                                                .timeout = timeout,
                                                .attempts = attempts});
  if (outcome.replied()) return outcome.telegram;
  if (outcome.failure == links::ExchangeFailure::no_reply && refused) return std::nullopt;
  throw links::ExchangeError(*outcome.failure, outcome.message);
}

bool Cerebellum::tell(const char* name, const hw::Bytes& message) {
  return exchange(name, message, hw::ReplyShape::ack, kReplyTimeout, kAttempts).has_value();
}

hw::OdometryReading Cerebellum::odometry() {
  const auto reply = exchange("GET_ODOM", hw::get_odometry(), hw::ReplyShape::ack_then_odometry, kReplyTimeout,
                              kAttempts);
  if (!reply) throw links::ExchangeError(links::ExchangeFailure::refused, "the robot refused GET_ODOM");
  // The format let through only an ACK followed by a block whose XOR checks.
  return *hw::parse_odometry_block(std::span(*reply).subspan(1));
}

hw::OdometryReading Cerebellum::start() {
  // A robot may be deaf for a moment after its port is opened (a USB
  // adapter powering up): the first message is given longer.
  const auto first = exchange("INIT", hw::init(), hw::ReplyShape::ack, kReplyTimeout, kFirstAttempts);
  if (!first) {
    if (!tell("DEINIT", hw::deinit()) || !tell("INIT", hw::init())) {
      throw std::runtime_error("the robot refused INIT twice, and DEINIT between them");
    }
  }
  const hw::OdometryReading reading = odometry();
  if (!tell("SET_ACCELERATIONS", hw::set_accelerations(hw::kStartAccelerations))) {
    throw std::runtime_error("the robot refused SET_ACCELERATIONS (10, 10)");
  }
  return reading;
}

}  // namespace playerkit::drivers::trogdor
