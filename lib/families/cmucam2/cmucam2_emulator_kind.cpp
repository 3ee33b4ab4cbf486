#include "families/cmucam2/cmucam2_emulator_kind.hpp"

#include <cstdio>

#include "emulators/emulator_option_reader.hpp"
#include "families/cmucam2/emulator/cmucam2_emulator.hpp"

namespace playerkit::families {

namespace {

// "pan,tilt,radius,red,green,blue": a disc of the synthetic scene.
emulators::cmucam2::Disc disc_option(const emulators::EmulatorOptionReader& reader, std::string_view name,
                                     const emulators::cmucam2::Disc& fallback) {
  if (!reader.has(name)) return fallback;
  const std::string text = reader.text(name, "");
  double pan = 0, tilt = 0, radius = 0;
  int red = 0, green = 0, blue = 0;
  char end = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf,%d,%d,%d%c", &pan, &tilt, &radius, &red, &green, &blue, &end) != 6 ||
      radius <= 0 || red < 0 || red > 255 || green < 0 || green > 255 || blue < 0 || blue > 255) {
    reader.fail(name, "expected pan,tilt,radius,red,green,blue (degrees, then 0-255 each)");
  }
  return {.pan = pan,
          .tilt = tilt,
          .radius = radius,
          .color = {static_cast<std::uint8_t>(red), static_cast<std::uint8_t>(green), static_cast<std::uint8_t>(blue)}};
}

}  // namespace

emulators::EmulatorKind cmucam2_emulator_kind() {
  return {
      .name = "cmucam2",
      .summary = "a CMUcam2 colour tracker with pan and tilt servos (ASCII, 115200 baud)",
      .interface_name = "blobfinder",
      .driver = "cmucam2",
      .mount = emulators::EmulatorMount::standalone,
      .options =
          {
              {"image", "", "a PPM (P6/P3) the camera looks at, one pixel a frame pixel; none: the synthetic scene"},
              {"blob", "10,0,6,220,30,30", "the synthetic scene's first disc: pan,tilt,radius (deg),red,green,blue"},
              {"blob2", "-15,5,4,30,200,40", "its second disc (radius 0 ... is refused; move it out of view instead)"},
              {"frame_ms", "30", "the frame time: one T packet each"},
              {"prompt_after_packet", "1", "1: ':' after a poll-mode T packet, as the camera; 0: none (1.5 then reads fresh data)"},
              {"servo_speed", "400", "servo slew, positions/s"},
              {"servo_resolution", "0.75", "degrees per servo position"},
          },
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld&) {
            emulators::Cmucam2EmulatorOptions options;
            options.frame_period = std::chrono::milliseconds(reader.integer("frame_ms", 30, 1, 1000));
            options.prompt_after_packet = reader.flag("prompt_after_packet", true);
            options.servo_speed = reader.number("servo_speed", 400, 1, 100000);
            options.degrees_per_position = reader.number("servo_resolution", 0.75, 0.01, 10);
            const std::string image = reader.text("image", "");
            if (!image.empty()) {
              return std::unique_ptr<emulators::DeviceEmulator>(std::make_unique<emulators::Cmucam2Emulator>(
                  emulators::cmucam2::Scene(emulators::cmucam2::read_ppm(image)), options));
            }
            const emulators::cmucam2::Disc first =
                disc_option(reader, "blob", {.pan = 10, .tilt = 0, .radius = 6, .color = {220, 30, 30}});
            const emulators::cmucam2::Disc second =
                disc_option(reader, "blob2", {.pan = -15, .tilt = 5, .radius = 4, .color = {30, 200, 40}});
            return std::unique_ptr<emulators::DeviceEmulator>(std::make_unique<emulators::Cmucam2Emulator>(
                emulators::cmucam2::Scene({first, second}, {25, 25, 25}), options));
          },
  };
}

}  // namespace playerkit::families
