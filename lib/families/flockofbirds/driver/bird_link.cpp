#include "families/flockofbirds/driver/bird_link.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace playerkit::drivers::flockofbirds {

BirdLink::BirdLink(links::ByteLink& link, std::function<bool()> stopping)
    : record_format_(fob::record_format_options()),
      value_format_(fob::scaling_reply_format_options()),
      record_reader_(link, record_format_, fob::kRecordSize),
      value_reader_(link, value_format_, fob::kScalingReplySize),
      records_exchanger_(record_reader_, stopping, "the bird"),
      value_exchanger_(value_reader_, std::move(stopping), "the bird") {}

void BirdLink::send(const std::vector<std::uint8_t>& bytes) {
  records_exchanger_.link().write_all(bytes, links::deadline_in(kReplyTimeout));
}

void BirdLink::wait_until_quiet() {
  const auto limit = links::deadline_in(kSettleLimit);
  while (records_exchanger_.next(links::deadline_in(kQuietGap))) {
    if (links::LinkClock::now() >= limit) {
      throw std::runtime_error("the bird keeps streaming after POINT (B); is another program talking to it?");
    }
  }
}

fob::PositionScaling BirdLink::start() {
  // Any record is the answer: one of a stream left running may come first.
  records_exchanger_.exchange({.name = "POINT (B)",
                               .bytes = fob::command(fob::CommandByte::point),
                               .matcher = {},
                               .timeout = kReplyTimeout,
                               .attempts = kAttempts});
  wait_until_quiet();
  send(fob::command(fob::CommandByte::position_angles));
  std::optional<fob::PositionScaling> scaling;
  std::vector<std::uint8_t> odd_answer;
  auto outcome = value_exchanger_.try_exchange(
      {.name = "EXAMINE VALUE position scaling (O 3)",
       .bytes = fob::examine_position_scaling(),
       .matcher =
           [&](std::span<const std::uint8_t> reply) {
             scaling = fob::scaling_from_reply(reply);
             if (!scaling) odd_answer.assign(reply.begin(), reply.end());
             return scaling ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
           },
       .timeout = kReplyTimeout,
       .attempts = kAttempts});
  if (!outcome.replied() && !odd_answer.empty() && outcome.failure == links::ExchangeFailure::no_reply) {
    char bytes[8];
    std::snprintf(bytes, sizeof bytes, "%02X %02X", odd_answer[0], odd_answer[1]);
    throw std::runtime_error(std::string("the bird answered its position scaling with ") + bytes +
                             ", neither 36\" (00 00) nor 72\" (01 00)");
  }
  (void)std::vector<std::uint8_t>(std::move(outcome).reply());  // throws what went wrong
  record_reader_.flush();
  send(fob::command(fob::CommandByte::stream));
  return *scaling;
}

BirdLink::Arrivals BirdLink::arrivals() {
  Arrivals arrived;
  // The reader, not the exchanger: only the reader reads a line that has
  // bytes when the deadline has already passed. Its one timeout a call is
  // the driver's own look (own_timeouts).
  while (const auto telegram = record_reader_.next(links::Deadline{})) {
    if (auto words = fob::decode_record(*telegram)) {
      arrived.newest = *words;
      ++arrived.count;
    }
  }
  return arrived;
}

void BirdLink::stop() { send(fob::command(fob::CommandByte::point)); }

}  // namespace playerkit::drivers::flockofbirds
