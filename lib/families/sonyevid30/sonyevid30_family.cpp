#include "families/sonyevid30/sonyevid30_family.hpp"

#include <cmath>
#include <cstdio>
#include <memory>

#include "emulators/emulator_option_reader.hpp"
#include "families/sonyevid30/emulator/evid30_emulator.hpp"
#include "families/sonyevid30/protocol/evid30_units.hpp"
#include "families/sonyevid30/protocol/visca.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace visca = hardware::sonyevid30;

// The pan/tilt inquiry moves nothing, and only a VISCA camera answers it
// with `90 50` and eight nibbles; an echo of it (a PTU-46 at power-up) has
// no 0x90 and is skipped by the framing.
std::optional<Identification> probe_sonyevid30(const ProbeContext& line) {
  const framing::TerminatedPacketFormat format(visca::reply_packet_options());
  links::FramedReader reader(line.link, format, visca::reply_packet_options().max_length);
  links::Exchanger exchanger(reader, {}, "the camera");
  std::optional<visca::PanTiltUnits> where;
  const auto answer = exchanger.try_exchange(
      {.name = "pan/tilt position inquiry",
       .bytes = visca::pan_tilt_inquiry(),
       .matcher =
           [&where](std::span<const std::uint8_t> telegram) {
             where = visca::pan_tilt_answer(visca::parse_reply(telegram));
             return where ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
           },
       .timeout = links::time_until(line.first_reply)});
  if (!answer.replied() || !where) return std::nullopt;
  char model[96];
  std::snprintf(model, sizeof model, "VISCA camera 1 (Sony EVI-D30), pan %ld tilt %ld degrees",
                std::lround(visca::pan_degrees(where->pan)), std::lround(visca::tilt_degrees(where->tilt)));
  return Identification{.driver = "sonyevid30",
                        .model = model,
                        .interface_name = "ptz",
                        .config_driver = "sonyevid30",
                        .note = {}};
}

emulators::EmulatorKind sonyevid30_emulator_kind() {
  return {
      .name = "sonyevid30",
      .summary = "a Sony EVI-D30 pan-tilt-zoom camera (VISCA, 9600 baud, pan +-100, tilt +-25 degrees)",
      .interface_name = "ptz",
      .driver = "sonyevid30",
      .mount = emulators::EmulatorMount::standalone,
      .options =
          {
              {"pan_speed", "80", "degrees/s at the top pan speed 0x18"},
              {"tilt_speed", "50", "degrees/s at the top tilt speed 0x14"},
              {"zoom_time", "2", "seconds from full wide to full tele"},
          },
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld&) {
            emulators::Evid30EmulatorOptions options;
            options.pan_top_speed = reader.number("pan_speed", options.pan_top_speed, 1, 1000);
            options.tilt_top_speed = reader.number("tilt_speed", options.tilt_top_speed, 1, 1000);
            options.zoom_travel_seconds = reader.number("zoom_time", options.zoom_travel_seconds, 0.01, 60);
            return std::unique_ptr<emulators::DeviceEmulator>(std::make_unique<emulators::Evid30Emulator>(options));
          },
  };
}

FamilySpec sonyevid30_family() {
  return {
      .name = "sonyevid30",
      .summary = "Sony EVI-D30 pan-tilt-zoom cameras (VISCA over RS-232)",
      .probes = {{.label = "EVI-D30 (VISCA)",
                  // The EVI-D30 speaks 9600 baud only (sonyevid30.md §1).
                  .bauds = {9600},
                  .line = {},
                  .ask = probe_sonyevid30}},
      .framing = {std::make_shared<framing::TerminatedPacketFormat>(visca::host_packet_options()),
                  std::make_shared<framing::TerminatedPacketFormat>(visca::reply_packet_options())},
      .emulators = {sonyevid30_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info sonyevid30",
              "player-drivers run sonyevid30 port=/dev/ttyS2 -n 5",
              "player-drivers run sonyevid30 port=/tmp/evid30 --trace",
              "player-drivers emulate sonyevid30 --link /tmp/evid30",
          },
  };
}

}  // namespace playerkit::families
