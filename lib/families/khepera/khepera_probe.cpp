// "Who are you?" on a line, Khepera style: E (read the wheel speeds), which
// changes nothing on the robot, answered by `e,<left>,<right>`.
#include <optional>
#include <string>

#include "families/khepera/khepera_family.hpp"
#include "families/khepera/protocol/khepera_commands.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace hw = hardware::khepera;

std::optional<Identification> probe_khepera(const ProbeContext& line) {
  const framing::TerminatedLineFormat format(hw::reply_line_options());
  links::FramedReader reader(line.link, format, hw::kLongestLine);
  links::Exchanger exchanger(reader, {}, "the Khepera");
  // LF first ends whatever was half typed before us; a BIOS answers no empty line.
  std::vector<std::uint8_t> request{'\n'};
  const auto ask = hw::encode_command(hw::read_speed());
  request.insert(request.end(), ask.begin(), ask.end());
  std::optional<hw::Message> speeds;
  const auto answer = exchanger.try_exchange(
      {.name = "E (wheel speeds)",
       .bytes = request,
       .matcher =
           [&speeds](std::span<const std::uint8_t> telegram) {
             speeds = hw::parse_reply_to(hw::letter::read_speed, framing::line_text(telegram), 2);
             return speeds ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
           },
       .timeout = links::time_until(line.first_reply)});
  if (!answer.replied() || !speeds) return std::nullopt;
  return Identification{
      .driver = "khepera",
      .model = "Khepera, wheels at " + std::to_string(speeds->values[0]) + "," + std::to_string(speeds->values[1]) +
               " pulses/10 ms",
      .interface_name = "position",
      .config_driver = "khepera_position",
      .note = "add ir:0 ( driver \"khepera_ir\" ) for its proximity sensors",
  };
}

}  // namespace playerkit::families
