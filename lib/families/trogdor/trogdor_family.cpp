#include "families/trogdor/trogdor_family.hpp"

#include <memory>
#include <string>

#include "emulators/emulator_option_reader.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/trogdor/emulator/trogdor_emulator.hpp"
#include "families/trogdor/protocol/trogdor_messages.hpp"
#include "families/trogdor/protocol/trogdor_reply_format.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace hw = hardware::trogdor;

// GET_ODOM changes nothing on the robot and its reply is unmistakable: an
// ACK and 18 bytes whose XOR checks.
std::optional<Identification> probe_trogdor(const ProbeContext& line) {
  const hw::TrogdorReplyFormat format(hw::ReplyShape::ack_then_odometry);
  links::FramedReader reader(line.link, format, hw::kLongestReply);
  links::Exchanger exchanger(reader, {}, "the robot");
  const auto answer = exchanger.try_exchange({.name = "GET_ODOM",
                                              .bytes = hw::get_odometry(),
                                              .matcher = {},
                                              .timeout = links::time_until(line.first_reply)});
  if (!answer.replied() || answer.telegram.size() != hw::kLongestReply) return std::nullopt;
  const auto reading = hw::parse_odometry_block(std::span(answer.telegram).subspan(1));
  if (!reading) return std::nullopt;
  return Identification{
      .driver = "trogdor",
      .model = "Botrics O-Bot (Trogdor) cerebellum, wheel counters " + std::to_string(reading->left_count) + " / " +
               std::to_string(reading->right_count),
      .interface_name = "position",
      .config_driver = "trogdor",
      .note = reading->encoder_error ? "the robot reports an encoder board error" : "",
  };
}

emulators::EmulatorKind trogdor_emulator_kind() {
  std::vector<emulators::EmulatorOptionDoc> options = emulators::mobile_base::robot_option_docs();
  options.push_back({"counts", "1000000", "both wheel counters at power-up (never 0)"});
  options.push_back({"encoder_error", "0", "1: every odometry reply reports an encoder board error"});
  return {
      .name = "trogdor",
      .summary = "a Botrics O-Bot (Trogdor) cerebellum: ACKed messages at 57600 baud, wheel counters, a 0.317 m axle",
      .interface_name = "position",
      .driver = "trogdor",
      .mount = emulators::EmulatorMount::robot,
      .options = std::move(options),
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld& world) {
            emulators::TrogdorEmulatorOptions settings;
            settings.body = emulators::mobile_base::read_robot_options(reader);
            settings.start_count = reader.integer("counts", settings.start_count, 1, 2'000'000'000);
            settings.encoder_error = reader.flag("encoder_error", false);
            return std::unique_ptr<emulators::DeviceEmulator>(
                std::make_unique<emulators::TrogdorEmulator>(settings, world.map));
          },
  };
}

FamilySpec trogdor_family() {
  return {
      .name = "trogdor",
      .summary = "Botrics O-Bot (\"Trogdor\") robots: the cerebellum's ACKed binary messages over RS-232",
      .probes = {{.label = "Trogdor (GET_ODOM)", .bauds = {57600}, .line = {}, .ask = probe_trogdor}},
      .framing = {std::make_shared<hw::TrogdorHostFormat>(), std::make_shared<hw::TrogdorReplyFormat>(hw::ReplyShape::guess)},
      .emulators = {trogdor_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info trogdor",
              "player-drivers run trogdor port=/dev/ttyUSB1 -n 5",
              "player-drivers run trogdor port=/tmp/trogdor --req motor-power state=1 --trace",
              "player-drivers emulate trogdor --link /tmp/trogdor",
          },
  };
}

}  // namespace playerkit::families
