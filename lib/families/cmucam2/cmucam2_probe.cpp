// "Who are you?" on a line, CMUcam2 style: a CR ends whatever the camera
// was doing (a stream included), then GV asks its version, which changes
// nothing. Only a version line naming a CMUcam counts.
#include <string>

#include "families/cmucam2/cmucam2_family.hpp"
#include "families/cmucam2/protocol/cmucam_protocol.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace cam = hardware::cmucam2;

std::optional<Identification> probe_cmucam2(const ProbeContext& line) {
  const framing::TerminatedLineFormat format(cam::reply_line_options());
  links::FramedReader reader(line.link, format, cam::kLongestLine);
  links::Exchanger exchanger(reader, {}, "the camera");
  std::optional<std::string> version;
  auto request = cam::encode("");
  const auto ask = cam::encode(cam::get_version());
  request.insert(request.end(), ask.begin(), ask.end());
  const auto answer = exchanger.try_exchange(
      {.name = "GV (version)",
       .bytes = request,
       .matcher =
           [&version](std::span<const std::uint8_t> telegram) {
             const std::string_view text = framing::line_text(telegram);
             if (text.find("CMUcam") == std::string_view::npos) return links::ReplyMatch::not_mine;
             version = std::string(text);
             return links::ReplyMatch::mine;
           },
       .timeout = links::time_until(line.first_reply)});
  if (!answer.replied() || !version) return std::nullopt;
  Identification found{
      .driver = "cmucam2",
      .model = *version,
      .interface_name = "blobfinder",
      .config_driver = "cmucam2",
      .note = {},
  };
  if (line.baud != 0 && line.baud != 115200) {
    found.note = "the camera runs at " + std::to_string(line.baud) +
                 " baud; the cmucam2 driver speaks 115200 as 1.5's did: set its jumpers to 115200";
  }
  return found;
}

}  // namespace playerkit::families
