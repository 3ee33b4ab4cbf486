#include "families/p2os/p2os_probe.hpp"

#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/frame_format.hpp"
#include "families/p2os/protocol/packet_types.hpp"
#include "families/p2os/protocol/sync.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace {

namespace p2os = hardware::p2os;

constexpr std::size_t kLongestP2osFrame = 3 + p2os::kMaxLengthByteFromRobot;
// After CLOSE the reference waits this long before it flushes and syncs again.
constexpr auto kAfterClose = std::chrono::milliseconds(400);

void write_command(links::ByteLink& link, std::uint8_t command, links::Deadline deadline) {
  const auto frame = p2os::command_frame(p2os::Command::plain(command));
  link.write_all(frame, std::max(deadline, links::deadline_in(std::chrono::milliseconds(100))));
}

// SYNC<n>, answered by its echo by `until`. Only to SYNC0 is any other
// packet a refusal (SIPs: a robot still connected from an earlier
// session); a stale SYNC1/2 echo is harmless.
links::ExchangeRequest sync_request(std::uint8_t sync, links::Deadline until) {
  return {.name = "SYNC" + std::to_string(sync),
          .bytes = p2os::command_frame(p2os::Command::plain(sync)),
          .matcher =
              [sync](std::span<const std::uint8_t> telegram) {
                const auto payload = p2os::frame_payload(telegram);
                if (payload.empty()) return links::ReplyMatch::not_mine;
                if (payload.front() == sync) return links::ReplyMatch::mine;
                const bool connected_robot = !p2os::is_sync_echo(payload.front());
                return sync == p2os::command::sync0 && connected_robot ? links::ReplyMatch::refusal
                                                                       : links::ReplyMatch::not_mine;
              },
          .timeout = links::time_until(until),
          .flush_first = sync == p2os::command::sync0};
}

Identification found(std::string model) {
  return {.driver = "p2os",
          .model = std::move(model),
          .interface_name = "position",
          .config_driver = "p2os_position",
          .note = "add the other p2os_* devices with the same port, or run them all: player-drivers run p2os port=..."};
}

}  // namespace

std::optional<Identification> probe_p2os(const ProbeContext& line) {
  const p2os::P2osFrameFormat format;
  links::FramedReader reader(line.link, format, kLongestP2osFrame);
  links::Exchanger exchanger(reader, {}, "the robot");  // probe_port looks at its stop between probes

  auto echo = exchanger.try_exchange(sync_request(p2os::command::sync0, line.first_reply));
  if (echo.failure == links::ExchangeFailure::refused) {
    write_command(line.link, p2os::command::close, line.finish);
    std::this_thread::sleep_until(std::min(line.finish, links::deadline_in(kAfterClose)));
    echo = exchanger.try_exchange(sync_request(p2os::command::sync0, line.finish));
  }
  if (!echo.replied()) return std::nullopt;

  if (!exchanger.try_exchange(sync_request(p2os::command::sync1, line.finish)).replied()) {
    return found("a P2OS controller (no SYNC1 echo)");
  }
  const links::ExchangeRequest sync2 = sync_request(p2os::command::sync2, line.finish);
  const auto reply = exchanger.try_exchange(sync2);
  if (!reply.replied()) return found("a P2OS controller (no SYNC2 reply)");
  // A robot answers SYNC0 and SYNC1 with the same packets, so only SYNC2
  // tells it from a line that echoes what it is sent: a loopback plug, a
  // modem, a PTU-46 fresh from power-up.
  if (reply.telegram == sync2.bytes) return std::nullopt;
  try {
    const auto names = p2os::decode_sync2_reply(p2os::frame_payload(reply.telegram));
    return found(names.robot_class + " " + names.subclass + " \"" + names.name + "\"");
  } catch (const p2os::DecodeError&) {
    return found("a P2OS controller (SYNC2 reply unreadable)");
  }
}

}  // namespace playerkit::families
