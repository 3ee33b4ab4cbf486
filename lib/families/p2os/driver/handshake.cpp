#include "families/p2os/driver/handshake.hpp"

#include <algorithm>
#include <array>
#include <sstream>
#include <string_view>

#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/packet_types.hpp"

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

enum class Wait { packet, none, stopped };

struct Received {
  Wait outcome = Wait::none;
  std::vector<std::uint8_t> payload;
};

Received wait_for_packet(links::FramedReader& reader, links::Deadline until, const std::stop_token& stop) {
  if (stop.stop_requested()) return {Wait::stopped, {}};
  if (auto telegram = reader.next(until)) {
    const auto payload = hw::frame_payload(*telegram);
    return {Wait::packet, {payload.begin(), payload.end()}};
  }
  return {stop.stop_requested() ? Wait::stopped : Wait::none, {}};
}

links::Deadline sooner(links::Deadline a, links::Deadline b) { return std::min(a, b); }

// Reads and drops telegrams until the line has been quiet for a while.
void drain_after_close(links::FramedReader& reader) {
  const links::Deadline limit = links::deadline_in(kCloseDrainLimit);
  while (links::LinkClock::now() < limit) {
    if (!reader.next(sooner(limit, links::deadline_in(kCloseQuiet)))) break;
  }
  reader.flush();
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

enum class Attempt { connected, no_answer, stopped };

// One SYNC0 ... SYNC2 exchange at the current speed.
Attempt attempt(links::ByteLink& link, links::FramedReader& reader, const HandshakeSettings& settings,
                links::Deadline deadline, const std::stop_token& stop, HandshakeResult& result) {
  reader.flush();
  send_command(link, hw::Command::plain(hw::command::sync0));
  std::uint8_t expecting = hw::packet_type::sync0;
  bool closed_once = false;
  links::Deadline until = sooner(deadline, links::deadline_in(settings.reply_timeout));
  for (;;) {
    const Received got = wait_for_packet(reader, until, stop);
    if (got.outcome == Wait::stopped) return Attempt::stopped;
    if (got.outcome == Wait::none) return Attempt::no_answer;
    const std::uint8_t type = got.payload.front();
    if (type == expecting) {
      if (type == hw::packet_type::sync2) {
        try {
          result.identity = hw::decode_sync2_reply(got.payload);
        } catch (const hw::DecodeError&) {
          return Attempt::no_answer;
        }
        send_command(link, hw::Command::plain(hw::command::open));
        send_command(link, hw::Command::plain(hw::command::pulse));
        return Attempt::connected;
      }
      ++expecting;
      send_command(link, hw::Command::plain(expecting));  // SYNC1, SYNC2
      until = sooner(deadline, links::deadline_in(settings.reply_timeout));
      continue;
    }
    if (hw::is_sync_echo(type)) continue;  // a stale echo of an earlier try
    if (closed_once) return Attempt::no_answer;
    // Still connected from an earlier session: close it and start over.
    send_command(link, hw::Command::plain(hw::command::close));
    drain_after_close(reader);
    closed_once = true;
    send_command(link, hw::Command::plain(hw::command::sync0));
    expecting = hw::packet_type::sync0;
    until = sooner(deadline, links::deadline_in(settings.reply_timeout));
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
  HandshakeResult result;
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
        switch (attempt(link, reader, settings, deadline, stop, result)) {
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
