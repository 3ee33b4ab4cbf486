// "Who are you?" on a line, PTU-46 style: ask the pan resolution, which no
// command changes, so probing leaves the unit as it was (echo and feedback
// mode included: an echo before the answer is allowed for).
#include <optional>
#include <string>
#include <string_view>

#include "families/ptu46/protocol/ptu_commands.hpp"
#include "families/ptu46/protocol/ptu_line_format.hpp"
#include "families/ptu46/protocol/ptu_replies.hpp"
#include "families/ptu46/ptu46_family.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace ptu = hardware::ptu46;

namespace {

// The answer to PR alone on its line, or behind the echo of "pr": never a
// '*' inside other traffic, such as the "*44" checksum that ends every NMEA
// sentence of a GPS receiver talking at the probe's speed.
std::optional<ptu::Reply> answer_to_pan_resolution(std::string_view line) {
  const auto skip_blanks = [](std::string_view text) {
    const std::size_t first = text.find_first_not_of(" \t");
    return first == std::string_view::npos ? std::string_view{} : text.substr(first);
  };
  std::string_view rest = skip_blanks(line);
  if (rest.size() >= 2 && (rest[0] == 'p' || rest[0] == 'P') && (rest[1] == 'r' || rest[1] == 'R')) {
    rest = skip_blanks(rest.substr(2));
  }
  if (rest.empty() || rest.front() != '*') return std::nullopt;
  return ptu::parse_reply(rest);
}

}  // namespace

std::optional<Identification> probe_ptu46(const ProbeContext& line) {
  const framing::TerminatedLineFormat format(ptu::reply_line_options());
  links::FramedReader reader(line.link, format, ptu::kLongestReplyLine);
  links::Exchanger exchanger(reader, {}, "the pan-tilt unit");
  std::optional<double> resolution;
  // A space first ends whatever was half typed before us.
  auto request = ptu::encode(ptu::empty());
  const auto ask = ptu::encode(ptu::query(ptu::Axis::pan, ptu::Quantity::resolution));
  request.insert(request.end(), ask.begin(), ask.end());
  const auto answer = exchanger.try_exchange(
      {.name = "PR (pan resolution)",
       .bytes = request,
       .matcher =
           [&resolution](std::span<const std::uint8_t> telegram) {
             const auto reply = answer_to_pan_resolution(framing::line_text(telegram));
             if (!reply || reply->kind != ptu::Reply::Kind::value || *reply->number <= 0) {
               return links::ReplyMatch::not_mine;
             }
             resolution = reply->number;
             return links::ReplyMatch::mine;
           },
       .timeout = links::time_until(line.first_reply)});
  if (!answer.replied() || !resolution) return std::nullopt;
  Identification found{
      .driver = "ptu46",
      .model = "PTU-46, " + ptu::value_line(*resolution).substr(2) + " arc-seconds a pan position",
      .interface_name = "ptz",
      .config_driver = "ptu46",
      .note = {},
  };
  if (line.baud != 0 && line.baud != 9600) {
    found.note = "the unit runs at " + std::to_string(line.baud) + " baud: add baudrate " +
                 std::to_string(line.baud) + " to the section";
  }
  return found;
}

}  // namespace playerkit::families
