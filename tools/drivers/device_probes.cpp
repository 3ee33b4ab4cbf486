#include "device_probes.hpp"

#include <thread>
#include <vector>

#include "hardware/p2os/commands.hpp"
#include "hardware/p2os/errors.hpp"
#include "hardware/p2os/frame.hpp"
#include "hardware/p2os/frame_format.hpp"
#include "hardware/p2os/packet_types.hpp"
#include "hardware/p2os/sync.hpp"
#include "hardware/sick/frame_format.hpp"
#include "hardware/sick/replies.hpp"
#include "hardware/sick/requests.hpp"
#include "hardware/sick/telegram.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::player_drivers {

namespace {

namespace p2os = hardware::p2os;
namespace sick = hardware::sick;

constexpr std::size_t kLongestP2osFrame = 3 + p2os::kMaxLengthByteFromRobot;
constexpr std::size_t kLongestSickTelegram = sick::kHeaderSize + sick::kMaxBodyLength + sick::kCrcSize;
// After CLOSE the reference waits this long before it flushes and syncs again.
constexpr auto kAfterClose = std::chrono::milliseconds(400);

void write_frame(links::ByteLink& link, const std::vector<std::uint8_t>& frame, links::Deadline deadline) {
  link.write_all(frame, std::max(deadline, links::deadline_in(std::chrono::milliseconds(100))));
}

// The type byte of the next P2OS packet, nullopt by the deadline.
std::optional<std::vector<std::uint8_t>> next_payload(links::FramedReader& reader, links::Deadline deadline) {
  const auto frame = reader.next(deadline);
  if (!frame) return std::nullopt;
  const auto payload = p2os::frame_payload(*frame);
  return std::vector<std::uint8_t>(payload.begin(), payload.end());
}

// Waits for a packet of type `wanted`; `on_other` sees every other one.
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

// Waits for the reply with `code` (scans of a streaming laser are skipped).
// Returns nullopt by the deadline.
std::optional<sick::Reply> await_reply(links::FramedReader& reader, std::uint8_t code, links::Deadline deadline) {
  while (auto telegram = reader.next(deadline)) {
    try {
      sick::Reply reply = sick::unframe_reply(*telegram);
      if (reply.code == code || reply.code == sick::kNotAcknowledged) return reply;
    } catch (const sick::TelegramError&) {
      // Framed but not a reply after all: keep listening.
    }
  }
  return std::nullopt;
}

enum class PasswordAnswer { none, accepted, other_model };

PasswordAnswer try_password(links::FramedReader& reader, links::ByteLink& link, sick::Model model,
                            links::Deadline deadline) {
  reader.flush();
  write_frame(link, sick::encode_request(sick::InstallationModeRequest{std::string(sick::installation_password(model))}),
              deadline);
  const auto reply = await_reply(reader, sick::kSwitchModeReply, deadline);
  if (!reply || reply->code != sick::kSwitchModeReply) return PasswordAnswer::none;
  try {
    const auto mode = sick::parse_mode_reply(*reply);
    if (mode.result == sick::ModeResult::ok) return PasswordAnswer::accepted;
    if (mode.result == sick::ModeResult::wrong_password) return PasswordAnswer::other_model;
  } catch (const sick::TelegramError&) {
  }
  return PasswordAnswer::none;
}

Identification sick_identity(links::FramedReader& reader, links::ByteLink& link, sick::Model model,
                             links::Deadline deadline) {
  if (model == sick::Model::pls) return {"sickpls", "PLS"};
  reader.flush();
  write_frame(link, sick::encode_request(sick::GetTypeRequest{}), deadline);
  const auto reply = await_reply(reader, sick::kTypeReply, deadline);
  if (reply && reply->code == sick::kTypeReply) {
    try {
      const std::string type = sick::parse_type_reply(*reply).trimmed();
      if (!type.empty()) return {"sicklms200", type};
    } catch (const sick::TelegramError&) {
    }
  }
  return {"sicklms200", "LMS (type not reported)"};
}

}  // namespace

std::optional<Identification> probe_p2os(links::ByteLink& link, const ProbeDeadlines& deadlines) {
  const p2os::P2osFrameFormat format;
  links::FramedReader reader(link, format, kLongestP2osFrame);
  reader.flush();
  const auto sync0 = p2os::command_frame(p2os::Command::plain(p2os::command::sync0));
  write_frame(link, sync0, deadlines.first_reply);

  bool closed = false;
  links::Deadline wait_until = deadlines.first_reply;
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
    write_frame(link, p2os::command_frame(p2os::Command::plain(p2os::command::close)), deadlines.finish);
    std::this_thread::sleep_until(std::min(deadlines.finish, links::deadline_in(kAfterClose)));
    reader.flush();
    write_frame(link, sync0, deadlines.finish);
    wait_until = deadlines.finish;
  }
  if (!echo) return std::nullopt;

  const auto ignore = [](std::uint8_t) { return true; };
  write_frame(link, p2os::command_frame(p2os::Command::plain(p2os::command::sync1)), deadlines.finish);
  if (!await_packet(reader, p2os::packet_type::sync1, deadlines.finish, ignore)) {
    return Identification{"p2os", "a P2OS controller (no SYNC1 echo)"};
  }
  write_frame(link, p2os::command_frame(p2os::Command::plain(p2os::command::sync2)), deadlines.finish);
  const auto reply = await_packet(reader, p2os::packet_type::sync2, deadlines.finish, ignore);
  if (!reply) return Identification{"p2os", "a P2OS controller (no SYNC2 reply)"};
  try {
    const auto names = p2os::decode_sync2_reply(*reply);
    return Identification{"p2os", names.robot_class + " " + names.subclass + " \"" + names.name + "\""};
  } catch (const p2os::DecodeError&) {
    return Identification{"p2os", "a P2OS controller (SYNC2 reply unreadable)"};
  }
}

std::optional<Identification> probe_sick(links::ByteLink& link, sick::Model first, const ProbeDeadlines& deadlines) {
  const auto format = sick::SickFrameFormat::replies();
  links::FramedReader reader(link, format, kLongestSickTelegram);
  const sick::Model other = first == sick::Model::lms200 ? sick::Model::pls : sick::Model::lms200;
  switch (try_password(reader, link, first, deadlines.first_reply)) {
    case PasswordAnswer::accepted:
      return sick_identity(reader, link, first, deadlines.finish);
    case PasswordAnswer::other_model:
      if (try_password(reader, link, other, deadlines.finish) == PasswordAnswer::accepted) {
        return sick_identity(reader, link, other, deadlines.finish);
      }
      return Identification{"sicklms200", "a SICK laser that refused both passwords"};
    case PasswordAnswer::none:
      break;
  }
  return std::nullopt;
}

}  // namespace playerkit::player_drivers
