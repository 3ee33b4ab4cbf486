#include "families/p2os/p2os_probe.hpp"

#include <algorithm>
#include <thread>
#include <vector>

#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/frame_format.hpp"
#include "families/p2os/protocol/packet_types.hpp"
#include "families/p2os/protocol/sync.hpp"
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

// The payload of the next P2OS packet, nullopt by the deadline.
std::optional<std::vector<std::uint8_t>> next_payload(links::FramedReader& reader, links::Deadline deadline) {
  const auto frame = reader.next(deadline);
  if (!frame) return std::nullopt;
  const auto payload = p2os::frame_payload(*frame);
  return std::vector<std::uint8_t>(payload.begin(), payload.end());
}

// Waits for a packet of type `wanted`; `on_other` sees every other one and
// says whether to keep waiting.
template <class OnOther>
std::optional<std::vector<std::uint8_t>> await_packet(links::FramedReader& reader, std::uint8_t wanted,
                                                      links::Deadline deadline, OnOther on_other) {
  while (auto payload = next_payload(reader, deadline)) {
    if (payload->empty()) continue;
    if (payload->front() == wanted) return payload;
    if (!on_other(payload->front())) return std::nullopt;
  }
  return std::nullopt;
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
  reader.flush();
  write_command(line.link, p2os::command::sync0, line.first_reply);

  bool closed = false;
  links::Deadline wait_until = line.first_reply;
  std::optional<std::vector<std::uint8_t>> echo;
  while (!echo) {
    bool connected_robot = false;
    echo = await_packet(reader, p2os::packet_type::sync0, wait_until, [&](std::uint8_t type) {
      // SIPs: a robot connected from an earlier session. A stale SYNC1/2 echo is harmless.
      connected_robot = !p2os::is_sync_echo(type);
      return !connected_robot;
    });
    if (echo || !connected_robot || closed) break;
    closed = true;
    write_command(line.link, p2os::command::close, line.finish);
    std::this_thread::sleep_until(std::min(line.finish, links::deadline_in(kAfterClose)));
    reader.flush();
    write_command(line.link, p2os::command::sync0, line.finish);
    wait_until = line.finish;
  }
  if (!echo) return std::nullopt;

  const auto ignore = [](std::uint8_t) { return true; };
  write_command(line.link, p2os::command::sync1, line.finish);
  if (!await_packet(reader, p2os::packet_type::sync1, line.finish, ignore)) {
    return found("a P2OS controller (no SYNC1 echo)");
  }
  write_command(line.link, p2os::command::sync2, line.finish);
  const auto reply = await_packet(reader, p2os::packet_type::sync2, line.finish, ignore);
  if (!reply) return found("a P2OS controller (no SYNC2 reply)");
  try {
    const auto names = p2os::decode_sync2_reply(*reply);
    return found(names.robot_class + " " + names.subclass + " \"" + names.name + "\"");
  } catch (const p2os::DecodeError&) {
    return found("a P2OS controller (SYNC2 reply unreadable)");
  }
}

}  // namespace playerkit::families
