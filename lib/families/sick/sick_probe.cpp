#include "families/sick/sick_probe.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "families/sick/protocol/frame_format.hpp"
#include "families/sick/protocol/replies.hpp"
#include "families/sick/protocol/requests.hpp"
#include "families/sick/protocol/telegram.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace {

namespace sick = hardware::sick;

constexpr std::size_t kLongestSickTelegram = sick::kHeaderSize + sick::kMaxBodyLength + sick::kCrcSize;

// `request`, answered by the reply with `code` by `until`; 92 says no. Scans
// of a streaming laser are skipped.
links::ExchangeRequest ask_for(const sick::Request& request, std::uint8_t code, links::Deadline until) {
  return {.name = sick::describe(request),
          .bytes = sick::encode_request(request),
          .matcher =
              [code](std::span<const std::uint8_t> telegram) {
                try {
                  const std::uint8_t got = sick::unframe_reply(telegram).code;
                  if (got == code) return links::ReplyMatch::mine;
                  if (got == sick::kNotAcknowledged) return links::ReplyMatch::refusal;
                } catch (const sick::TelegramError&) {
                  // Framed but not a reply after all: keep listening.
                }
                return links::ReplyMatch::not_mine;
              },
          .timeout = links::time_until(until)};
}

enum class PasswordAnswer { none, accepted, other_model };

PasswordAnswer password_answer(const links::ExchangeOutcome& answer) {
  if (!answer.replied()) return PasswordAnswer::none;
  try {
    const auto mode = sick::parse_mode_reply(sick::unframe_reply(answer.telegram));
    if (mode.result == sick::ModeResult::ok) return PasswordAnswer::accepted;
    if (mode.result == sick::ModeResult::wrong_password) return PasswordAnswer::other_model;
  } catch (const sick::TelegramError&) {
  }
  return PasswordAnswer::none;
}

PasswordAnswer ask_password(links::Exchanger& exchanger, sick::Model model, links::Deadline deadline,
                            bool flush_first) {
  links::ExchangeRequest request = ask_for(
      sick::InstallationModeRequest{std::string(sick::installation_password(model))}, sick::kSwitchModeReply, deadline);
  request.flush_first = flush_first;
  return password_answer(exchanger.try_exchange(request));
}

// Takes the mode reply still on its way, so that it answers nothing else.
void await_mode_reply(links::Exchanger& exchanger, links::Deadline deadline) {
  while (const auto telegram = exchanger.next(deadline)) {
    try {
      if (sick::unframe_reply(*telegram).code == sick::kSwitchModeReply) return;
    } catch (const sick::TelegramError&) {
    }
  }
}

// A mode reply does not say which password it answers. The probe before this
// one asked the other model's password at this rate and gave up waiting; on
// a loaded machine its "accepted" can arrive now, after this request went
// out. So an accepted password is asked once more, nothing flushed: the laser
// that has it accepts it again; the other model's "wrong password" (to the
// first request) says the "accepted" was late, and the answer to the second
// request is taken off the line before anything else is asked.
PasswordAnswer try_password(links::Exchanger& exchanger, sick::Model model, links::Deadline first_reply,
                            links::Deadline finish) {
  const PasswordAnswer first = ask_password(exchanger, model, first_reply, /*flush_first=*/true);
  if (first != PasswordAnswer::accepted) return first;
  const PasswordAnswer again = ask_password(exchanger, model, finish, /*flush_first=*/false);
  if (again == PasswordAnswer::other_model) await_mode_reply(exchanger, finish);
  return again;
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

Identification identity(links::Exchanger& exchanger, const ProbeContext& line, sick::Model model) {
  if (model == sick::Model::pls) return laser("sickpls", "PLS", line.baud);
  const auto answer = exchanger.try_exchange(ask_for(sick::GetTypeRequest{}, sick::kTypeReply, line.finish));
  if (answer.replied()) {
    try {
      const std::string type = sick::parse_type_reply(sick::unframe_reply(answer.telegram)).trimmed();
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
  links::Exchanger exchanger(reader, {}, "the laser");  // probe_port looks at its stop between probes
  const sick::Model other = first == sick::Model::lms200 ? sick::Model::pls : sick::Model::lms200;
  switch (try_password(exchanger, first, line.first_reply, line.finish)) {
    case PasswordAnswer::accepted:
      return identity(exchanger, line, first);
    case PasswordAnswer::other_model:
      if (try_password(exchanger, other, line.finish, line.finish) == PasswordAnswer::accepted) {
        return identity(exchanger, line, other);
      }
      return laser("sicklms200", "a SICK laser that refused both passwords", line.baud);
    case PasswordAnswer::none:
      break;
  }
  return std::nullopt;
}

}  // namespace playerkit::families
