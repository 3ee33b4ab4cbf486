// "Who are you?" on a line, PowerCube style: each module of the wrist is
// asked its position, which changes nothing (no reset, no homing).
#include <string>

#include "families/amtecpowercube/amtecpowercube_family.hpp"
#include "families/amtecpowercube/protocol/powercube_frames.hpp"
#include "families/amtecpowercube/protocol/powercube_units.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace pc = hardware::powercube;

namespace {

// The module's position in degrees, or nullopt when it does not answer.
std::optional<double> ask_position(links::Exchanger& exchanger, pc::Module module, links::Deadline deadline) {
  std::optional<double> degrees;
  const auto answer = exchanger.try_exchange(
      {.name = "module " + std::to_string(static_cast<int>(module)) + " position",
       .bytes = pc::encode(module, pc::get_data(pc::Parameter::position)),
       .matcher =
           [&](std::span<const std::uint8_t> telegram) {
             const auto frame = pc::decode(telegram);
             if (!frame || frame->module != static_cast<std::uint8_t>(module)) return links::ReplyMatch::not_mine;
             const auto value = pc::reply_value(*frame, pc::Parameter::position);
             if (!value) return links::ReplyMatch::not_mine;
             degrees = pc::degrees(pc::float_from_bits(*value));
             return links::ReplyMatch::mine;
           },
       .timeout = links::time_until(deadline)});
  return answer.replied() ? degrees : std::nullopt;
}

}  // namespace

std::optional<Identification> probe_amtecpowercube(const ProbeContext& line) {
  const framing::DleStuffedFormat format(pc::frame_options());
  links::FramedReader reader(line.link, format, pc::kLongestFrame);
  links::Exchanger exchanger(reader, {}, "the PowerCube");
  const auto pan = ask_position(exchanger, pc::Module::pan, line.first_reply);
  // A wrist without its pan module still says who it is through its tilt.
  const auto tilt = ask_position(exchanger, pc::Module::tilt, line.finish);
  if (!pan && !tilt) return std::nullopt;
  Identification found{
      .driver = "amtecpowercube",
      .model = "Amtec PowerCube wrist, pan module 12 and tilt module 11",
      .interface_name = "ptz",
      .config_driver = "amtecpowercube",
      .note = {},
  };
  if (!pan || !tilt) {
    found.model = std::string("Amtec PowerCube, only the ") + (pan ? "pan module 12" : "tilt module 11") + " answers";
    found.note = "the driver needs both modules: pan 12 and tilt 11";
  }
  return found;
}

}  // namespace playerkit::families
