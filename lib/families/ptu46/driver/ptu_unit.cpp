#include "families/ptu46/driver/ptu_unit.hpp"

#include <cmath>
#include <stdexcept>

#include "families/ptu46/protocol/ptu_line_format.hpp"
#include "families/ptu46/protocol/ptu_units.hpp"

namespace playerkit::drivers::ptu46 {

bool UnitLimits::plausible() const {
  for (const AxisLimits* axis : {&pan, &tilt}) {
    if (axis->degrees_per_position <= 0 || axis->min_position == 0 || axis->max_position == 0) return false;
  }
  return true;
}

PtuUnit::PtuUnit(links::ByteLink& link, std::function<bool()> stopping)
    : format_(ptu::reply_line_options()),
      reader_(link, format_, ptu::kLongestReplyLine),
      exchanger_(reader_, std::move(stopping), "the pan-tilt unit") {}

ptu::Reply PtuUnit::ask(const ptu::Command& command, std::chrono::milliseconds timeout) {
  std::optional<ptu::Reply> reply;
  exchanger_.exchange({.name = "'" + command.text + "'",
                       .bytes = ptu::encode(command),
                       .matcher =
                           [&reply](std::span<const std::uint8_t> telegram) {
                             reply = ptu::parse_reply_after_echo(framing::line_text(telegram));
                             return reply ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
                           },
                       .timeout = timeout,
                       .attempts = kAttempts});
  return *reply;
}

std::int64_t PtuUnit::integer(const ptu::Command& command) {
  const ptu::Reply reply = ask(command);
  if (reply.kind != ptu::Reply::Kind::value) {
    throw std::runtime_error("the pan-tilt unit answered '" + command.text + "' with no number" +
                             (reply.text.empty() ? "" : ": " + reply.text));
  }
  return std::llround(*reply.number);
}

UnitLimits PtuUnit::read_limits() {
  UnitLimits limits;
  for (const ptu::Axis axis : {ptu::Axis::tilt, ptu::Axis::pan}) {
    const ptu::Reply resolution = ask(ptu::query(axis, ptu::Quantity::resolution));
    AxisLimits& of = axis == ptu::Axis::pan ? limits.pan : limits.tilt;
    of.degrees_per_position = resolution.number ? ptu::degrees_per_position(*resolution.number) : 0.0;
  }
  for (const ptu::Axis axis : {ptu::Axis::pan, ptu::Axis::tilt}) {
    AxisLimits& of = axis == ptu::Axis::pan ? limits.pan : limits.tilt;
    of.min_position = integer(ptu::query(axis, ptu::Quantity::min_position));
    of.max_position = integer(ptu::query(axis, ptu::Quantity::max_position));
  }
  for (const ptu::Axis axis : {ptu::Axis::pan, ptu::Axis::tilt}) {
    AxisLimits& of = axis == ptu::Axis::pan ? limits.pan : limits.tilt;
    of.lower_speed = integer(ptu::query(axis, ptu::Quantity::lower_speed));
    of.upper_speed = integer(ptu::query(axis, ptu::Quantity::upper_speed));
  }
  return limits;
}

UnitLimits PtuUnit::start() {
  // A lone delimiter ends whatever an earlier session left half typed; it
  // gets no answer, and the next exchange drops whatever arrives.
  const auto delimiter = ptu::encode(ptu::empty());
  exchanger_.link().write_all(delimiter, links::deadline_in(kReplyTimeout));
  ask(ptu::terse_feedback());
  ask(ptu::echo_off());
  ask(ptu::set_control_mode(ptu::ControlMode::independent));
  UnitLimits limits = read_limits();
  if (limits.plausible()) return limits;
  const ptu::Reply reset = ask(ptu::reset(), kResetTimeout);
  if (reset.kind != ptu::Reply::Kind::reset) {
    throw std::runtime_error("the pan-tilt unit reported a zero resolution or limit, and its reset failed" +
                             (reset.text.empty() ? std::string() : ": " + reset.text));
  }
  limits = read_limits();
  if (!limits.plausible()) {
    throw std::runtime_error("the pan-tilt unit still reports a zero resolution or limit after a reset; "
                             "is the serial port correct?");
  }
  return limits;
}

std::uint64_t PtuUnit::drop_unsolicited() {
  std::uint64_t dropped = 0;
  while (exchanger_.next(links::LinkClock::now())) ++dropped;
  return dropped;
}

}  // namespace playerkit::drivers::ptu46
