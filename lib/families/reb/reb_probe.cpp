// "Who are you?" on a line, REB style: read the right motor's position
// counter, which changes nothing. LPRSerCom answers one value and then its
// prompt ':'; a Khepera's SerCom answers H with two values and no prompt,
// so the two are not taken for each other.
#include <optional>
#include <string>

#include "families/reb/protocol/reb_lines.hpp"
#include "families/reb/reb_family.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace reb = hardware::reb;

std::optional<Identification> probe_reb(const ProbeContext& line) {
  const framing::TerminatedLineFormat format(reb::reply_line_options());
  links::FramedReader reader(line.link, format, reb::kLongestLine);
  links::Exchanger exchanger(reader, {}, "the REB");
  // A CR first ends whatever was half typed before us.
  auto request = reb::encode(reb::read_position(reb::Motor::right));
  request.insert(request.begin(), '\r');
  const auto answer = exchanger.try_exchange(
      {.name = "H,0 (right motor position)",
       .bytes = request,
       .matcher =
           [](std::span<const std::uint8_t> telegram) {
             const auto reply = reb::parse_reply(framing::line_text(telegram));
             return reply && reply->letter == 'h' && reply->values.size() == 1 ? links::ReplyMatch::mine
                                                                              : links::ReplyMatch::not_mine;
           },
       .timeout = links::time_until(line.first_reply)});
  if (!answer.replied()) return std::nullopt;
  while (auto telegram = exchanger.next(line.finish)) {
    if (reb::is_prompt(framing::line_text(*telegram))) {
      return Identification{
          .driver = "reb",
          .model = "REB with LPRSerCom (UBot)",
          .interface_name = "position",
          .config_driver = "reb_position",
          .note = "add ir:0 ( driver \"reb_ir\" ) and power:0 ( driver \"reb_power\" ) for the rest of the robot; "
                  "subclass \"fast\" for the fast UBot's encoders",
      };
    }
  }
  return std::nullopt;
}

}  // namespace playerkit::families
