// "Who are you?" on a line, ER1 style: read both motors' position counts,
// which changes nothing (the robot keeps still and its odometry whole).
// Each answer must be the 6 bytes of a position reply, summing to 0, with
// status 0: a sum of 0 alone turns up in any stream of text (an NMEA
// receiver's sentences were taken for an ER1), a NUL byte never does.
#include <cstdio>
#include <optional>
#include <string>

#include "families/er1/er1_family.hpp"
#include "families/er1/protocol/er1_commands.hpp"
#include "families/er1/protocol/er1_frame_format.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace er1 = hardware::er1;

std::optional<Identification> probe_er1(const ProbeContext& line) {
  er1::ReplyFormat format(er1::reply_length(er1::opcode::read_position));
  links::FramedReader reader(line.link, format, er1::ReplyFormat::kLongest);
  links::Exchanger exchanger(reader, {}, "the ER1's controller");
  std::int32_t counts[2] = {0, 0};
  for (const er1::Motor motor : {er1::Motor::port0, er1::Motor::port1}) {
    const auto answer = exchanger.try_exchange(
        {.name = "position of motor " + std::to_string(static_cast<int>(motor)),
         .bytes = er1::read_position(motor),
         .matcher = {},
         .timeout = links::time_until(motor == er1::Motor::port0 ? line.first_reply : line.finish)});
    if (!answer.replied() || answer.telegram.empty() || answer.telegram[0] != 0x00) return std::nullopt;
    counts[static_cast<int>(motor)] = er1::position_count(answer.telegram).value_or(0);
  }
  char model[120];
  std::snprintf(model, sizeof model, "ER1 Robot Control Module, motor counts %d and %d", counts[0], counts[1]);
  return Identification{
      .driver = "er1_position",
      .model = model,
      .interface_name = "position",
      .config_driver = "er1_position",
      .note = "if the robot turns the wrong way, add motor_dir -1 (its left motor is on the motor-1 port)",
  };
}

}  // namespace playerkit::families
