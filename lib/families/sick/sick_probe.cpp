#include "families/sick/sick_probe.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "families/sick/protocol/frame_format.hpp"
#include "families/sick/protocol/replies.hpp"
#include "families/sick/protocol/requests.hpp"
#include "families/sick/protocol/telegram.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace {

namespace sick = hardware::sick;

constexpr std::size_t kLongestSickTelegram = sick::kHeaderSize + sick::kMaxBodyLength + sick::kCrcSize;

void write_request(links::ByteLink& link, const std::vector<std::uint8_t>& telegram, links::Deadline deadline) {
  link.write_all(telegram, std::max(deadline, links::deadline_in(std::chrono::milliseconds(100))));
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
  write_request(link,
                sick::encode_request(sick::InstallationModeRequest{std::string(sick::installation_password(model))}),
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

Identification laser(std::string driver, std::string model, int baud) {
  std::string note;
  if (baud == 19200 || baud == 500000) {
    note = "the laser runs at " + std::to_string(baud) +
           " baud; drivers look for it at 38400 and 9600 first: power-cycle it (it starts at 9600)";
  }
  return {.driver = driver,
          .model = std::move(model),
          .interface_name = "laser",
          .config_driver = driver,
          .note = std::move(note)};
}

Identification identity(links::FramedReader& reader, const ProbeContext& line, sick::Model model) {
  if (model == sick::Model::pls) return laser("sickpls", "PLS", line.baud);
  reader.flush();
  write_request(line.link, sick::encode_request(sick::GetTypeRequest{}), line.finish);
  const auto reply = await_reply(reader, sick::kTypeReply, line.finish);
  if (reply && reply->code == sick::kTypeReply) {
    try {
      const std::string type = sick::parse_type_reply(*reply).trimmed();
      if (!type.empty()) return laser("sicklms200", type, line.baud);
    } catch (const sick::TelegramError&) {
    }
  }
  return laser("sicklms200", "LMS (type not reported)", line.baud);
}

}  // namespace

std::optional<Identification> probe_sick(const ProbeContext& line, sick::Model first) {
  const auto format = sick::SickFrameFormat::replies();
  links::FramedReader reader(line.link, format, kLongestSickTelegram);
  const sick::Model other = first == sick::Model::lms200 ? sick::Model::pls : sick::Model::lms200;
  switch (try_password(reader, line.link, first, line.first_reply)) {
    case PasswordAnswer::accepted:
      return identity(reader, line, first);
    case PasswordAnswer::other_model:
      if (try_password(reader, line.link, other, line.finish) == PasswordAnswer::accepted) {
        return identity(reader, line, other);
      }
      return laser("sicklms200", "a SICK laser that refused both passwords", line.baud);
    case PasswordAnswer::none:
      break;
  }
  return std::nullopt;
}

}  // namespace playerkit::families
