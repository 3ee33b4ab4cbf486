#include "families/p2os/driver/handshake.hpp"

#include <algorithm>
#include <array>
#include <sstream>
#include <string_view>
#include <utility>

#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/packet_types.hpp"
#include "links/exchange.hpp"

namespace playerkit::drivers::p2os {

namespace hw = hardware::p2os;
using namespace std::chrono_literals;

namespace {

constexpr auto kWriteBudget = 500ms;
// After CLOSE, a robot may finish the SIP it was sending: wait for this
// much quiet (at most kCloseDrainLimit) before synchronising again.
constexpr auto kCloseQuiet = 150ms;
constexpr auto kCloseDrainLimit = 1s;
// What the radio modem says once it has dialled the robot's modem, and how
// long 1.5 waited for it.
constexpr std::string_view kRadioConnected = "ected to addres";
constexpr auto kRadioWait = 3400ms;

links::Deadline sooner(links::Deadline a, links::Deadline b) { return std::min(a, b); }

// Reads and drops telegrams until the line has been quiet for a while;
// false when the driver is stopping.
bool drain_after_close(links::Exchanger& exchanger) {
  const links::Deadline limit = links::deadline_in(kCloseDrainLimit);
  try {
    while (links::LinkClock::now() < limit) {
      if (!exchanger.next(sooner(limit, links::deadline_in(kCloseQuiet)))) break;
    }
  } catch (const links::ExchangeError&) {
    return false;
  }
  exchanger.reader().flush();
  return true;
}

bool dial_radio(links::ByteLink& link, links::Deadline deadline) {
  static constexpr std::string_view kDial = "WMS2\r";
  link.write_all(std::span(reinterpret_cast<const std::uint8_t*>(kDial.data()), kDial.size()),
                 links::deadline_in(kWriteBudget));
  const links::Deadline until = sooner(deadline, links::deadline_in(kRadioWait));
  std::string heard;
  std::array<std::uint8_t, 256> buffer{};
  while (links::LinkClock::now() < until) {
    const std::size_t count = link.read_some(buffer, until);
    heard.append(reinterpret_cast<const char*>(buffer.data()), count);
    if (heard.find(kRadioConnected) != std::string::npos) return true;
  }
  return false;
}

// SYNC<n>: the reply's type byte is the command's number (SYNC2's reply
// also names the robot).
// A stale echo of an earlier try is skipped; anything else (SIPs) is a
// robot still connected from an earlier session, refusing to synchronise.
links::ExchangeRequest sync_request(std::uint8_t sync, links::LinkClock::duration timeout) {
  return {.name = "SYNC" + std::to_string(sync),
          .bytes = hw::command_frame(hw::Command::plain(sync)),
          .matcher =
              [sync](std::span<const std::uint8_t> telegram) {
                const auto payload = hw::frame_payload(telegram);
                if (!payload.empty() && payload.front() == sync) return links::ReplyMatch::mine;
                if (payload.empty() || hw::is_sync_echo(payload.front())) return links::ReplyMatch::not_mine;
                return links::ReplyMatch::refusal;
              },
          .timeout = timeout,
          // What comes after SYNC0's echo belongs to this handshake.
          .flush_first = sync == hw::command::sync0};
}

// SYNC0, SYNC1, SYNC2 at the current speed: SYNC2's reply, or the failure.
links::ExchangeOutcome synchronise(links::Exchanger& exchanger, const HandshakeSettings& settings,
                                   links::Deadline deadline) {
  links::ExchangeOutcome outcome;
  for (std::uint8_t sync = hw::command::sync0; sync <= hw::command::sync2; ++sync) {
    const auto timeout = std::min<links::LinkClock::duration>(settings.reply_timeout, links::time_until(deadline));
    outcome = exchanger.try_exchange(sync_request(sync, timeout));
    if (!outcome.replied()) break;
  }
  return outcome;
}

enum class Attempt { connected, no_answer, stopped };

Attempt attempt(links::ByteLink& link, links::Exchanger& exchanger, const HandshakeSettings& settings,
                links::Deadline deadline, HandshakeResult& result) {
  for (bool closed_once = false;; closed_once = true) {
    const links::ExchangeOutcome outcome = synchronise(exchanger, settings, deadline);
    if (outcome.replied()) {
      try {
        result.identity = hw::decode_sync2_reply(hw::frame_payload(outcome.telegram));
      } catch (const hw::DecodeError&) {
        return Attempt::no_answer;
      }
      send_command(link, hw::Command::plain(hw::command::open));
      send_command(link, hw::Command::plain(hw::command::pulse));
      return Attempt::connected;
    }
    if (outcome.failure == links::ExchangeFailure::stopped) return Attempt::stopped;
    if (outcome.failure == links::ExchangeFailure::no_reply || closed_once) return Attempt::no_answer;
    // Still connected from an earlier session: close it and start over.
    send_command(link, hw::Command::plain(hw::command::close));
    if (!drain_after_close(exchanger)) return Attempt::stopped;
  }
}

std::string speeds_tried(const std::vector<int>& bauds) {
  std::ostringstream out;
  for (std::size_t i = 0; i < bauds.size(); ++i) out << (i == 0 ? "" : ", ") << bauds[i];
  return out.str();
}

}  // namespace

void send_command(links::ByteLink& link, const hw::Command& command) {
  link.write_all(hw::command_frame(command), links::deadline_in(kWriteBudget));
}

std::optional<HandshakeResult> run_handshake(links::ByteLink& link, links::FramedReader& reader,
                                             const HandshakeSettings& settings, links::Deadline deadline,
                                             const std::stop_token& stop) {
  const auto started = links::LinkClock::now();
  links::Exchanger exchanger(reader, [&stop] { return stop.stop_requested(); }, "the robot");
  HandshakeResult result;
  bool first_try = true;
  if (settings.radio) result.radio_connected = dial_radio(link, deadline);

  // A link without a line speed of its own (TCP) is simply asked again.
  const bool has_baud = link.baud() != 0 && !settings.bauds.empty();
  const std::vector<int> bauds = has_baud ? settings.bauds : std::vector<int>{0};
  const int tries = std::max(1, settings.tries_per_baud);
  for (std::size_t round = 0;; ++round) {
    for (const int baud : bauds) {
      if (baud != 0 && link.baud() != baud) link.set_baud(baud);
      for (int t = 0; t < tries; ++t) {
        if (links::LinkClock::now() >= deadline) {
          const auto waited = std::chrono::duration<double>(links::LinkClock::now() - started).count();
          std::ostringstream message;
          message.precision(2);
          message << "no answer from a P2OS robot on " << settings.port << " in " << waited << " s ("
                  << (has_baud ? "SYNC0 sent at " + speeds_tried(bauds) + " baud" : std::string("SYNC0 sent"))
                  << (round > 0 ? ", every speed more than once" : "")
                  << "): check that the robot is switched on and that this port is wired to its HOST "
                     "serial port";
          if (settings.radio && !result.radio_connected) message << " (the radio modem never reported a connection)";
          throw HandshakeFailed(message.str());
        }
        // Every SYNC0 after the first is the same request sent again.
        if (!std::exchange(first_try, false)) link.counters().retries.add();
        switch (attempt(link, exchanger, settings, deadline, result)) {
          case Attempt::connected:
            result.baud = has_baud ? link.baud() : 0;
            return result;
          case Attempt::stopped: return std::nullopt;
          case Attempt::no_answer: break;
        }
      }
    }
  }
}

}  // namespace playerkit::drivers::p2os
