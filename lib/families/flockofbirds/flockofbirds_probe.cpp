// "Who are you?" on a line, Flock of Birds style: POINT, which any bird
// answers with one record (and which ends a stream), then EXAMINE VALUE of
// the position scaling, whose two-byte answer 00 00 or 01 00 confirms it.
// The bird is left in point mode, as the drivers leave it.
#include <string>

#include "families/flockofbirds/flockofbirds_family.hpp"
#include "families/flockofbirds/protocol/bird_commands.hpp"
#include "families/flockofbirds/protocol/bird_record.hpp"
#include "framing/fixed_length_format.hpp"
#include "framing/phasing_bit_format.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace fob = hardware::flockofbirds;

std::optional<Identification> probe_flockofbirds(const ProbeContext& line) {
  const framing::PhasingBitFormat record_format(fob::record_format_options());
  links::FramedReader records(line.link, record_format, fob::kRecordSize);
  links::Exchanger record_exchanger(records, {}, "the bird");
  const auto point = record_exchanger.try_exchange({.name = "POINT (B)",
                                                    .bytes = fob::command(fob::CommandByte::point),
                                                    .matcher = {},
                                                    .timeout = links::time_until(line.first_reply),
                                                    .attempts = 1});
  if (!point.replied()) return std::nullopt;
  // A bird that was streaming may have more records under way.
  while (record_exchanger.next(links::deadline_in(std::chrono::milliseconds(60)))) {
    if (links::LinkClock::now() >= line.finish) return std::nullopt;
  }
  const framing::FixedLengthFormat value_format(fob::scaling_reply_format_options());
  links::FramedReader values(line.link, value_format, fob::kScalingReplySize);
  links::Exchanger value_exchanger(values, {}, "the bird");
  std::optional<fob::PositionScaling> scaling;
  const auto examined = value_exchanger.try_exchange(
      {.name = "EXAMINE VALUE position scaling (O 3)",
       .bytes = fob::examine_position_scaling(),
       .matcher =
           [&scaling](std::span<const std::uint8_t> reply) {
             scaling = fob::scaling_from_reply(reply);
             return scaling ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
           },
       .timeout = links::time_until(line.finish),
       .attempts = 1});
  if (!examined.replied() || !scaling) return std::nullopt;
  Identification found{
      .driver = "flockofbirds",
      .model = "Flock of Birds, " + std::to_string(fob::full_scale_inches(*scaling)) + "\" position scaling",
      .interface_name = "position3d",
      .config_driver = "flockofbirds",
      .note = {},
  };
  if (line.baud != 0 && line.baud != 115200) {
    found.note = "the bird runs at " + std::to_string(line.baud) + " baud: add baudrate " + std::to_string(line.baud) +
                 " to the section";
  }
  return found;
}

}  // namespace playerkit::families
